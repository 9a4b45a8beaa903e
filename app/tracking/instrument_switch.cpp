#include "tracking/instrument_switch.h"

namespace microsim::tracking {

sim::Instrument switchedInstrument(sim::Instrument held) {
  return held == sim::Instrument::Forceps ? sim::Instrument::Scissors : sim::Instrument::Forceps;
}

void switchInstrument(sim::HandInput& hand) {
  hand.instrument = switchedInstrument(hand.instrument);
  hand.closure = 0.0;
}

}  // namespace microsim::tracking
