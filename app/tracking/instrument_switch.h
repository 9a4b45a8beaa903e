#pragma once
// What a hand holds when the trainee switches instruments without a tracker (the keyboard's
// T, a game controller's Y button, a 3D mouse's third button): the forceps and the
// microscissors by turns (tools/microscissors.h). Whatever else a hand held (a scalpel from a
// tracker, a needle holder) goes back to the forceps. The new instrument is taken up open:
// scissors taken up closed would cut nothing (the engine cuts only on a closing in the hand),
// and a forceps put down opens anyway. The sources swap only where the scene declares scissors
// (ManualSource::placeTools, RateToolSource::setScissorsInScene).

#include "microsim/sim/scene/input_frame.h"

namespace microsim::tracking {

/// The instrument a switch hands over for `held`.
sim::Instrument switchedInstrument(sim::Instrument held);

/// Puts `hand`'s instrument down and takes up the switched one, open.
void switchInstrument(sim::HandInput& hand);

}  // namespace microsim::tracking
