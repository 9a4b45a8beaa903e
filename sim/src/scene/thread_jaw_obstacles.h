#pragma once
// The forceps' jaws as the thread meets them (suture_contact.h's capsules), open or closed.
//
// Each jaw's tapered capsule (jaw_contact.h) becomes two: the tip half as thick as its middle,
// the heel half as thick as the heel, so the thread keeps off every point of the jaw. Jaws
// are solid to the thread whether they are closed or open, so turns wound round a forceps stay
// on its jaws while it opens to take the tail (the instrument tie, issue 19). While thread
// lies between opened jaws, each capsule is made thin enough to leave it a thread's radius
// clear: what the jaws close on is theirs to take, and capsules round their axes, which
// overlap long before the gripping faces meet, would squeeze it out first; the turns round the
// jaws still meet a rod. Jaws that hold the thread are solid to all of it but the held run:
// the held node and the chain on either side of it inside the jaws' reach pass through their
// capsules (Capsule::freeFirst..freeLast), so turns wound on the jaws stay on while they take
// the tail and draw it back, and another strand is pushed ahead. Opened jaws are left out
// with a needle lying free (nothing holds the suture) within 0.5 mm of them: the
// rigid needle would be knocked away by the jaws reaching round it, and a trainee steering
// them with keys could hardly take it (the hands test of lesson 2 missed its grip one run in
// two). A needle hanging from a thread another forceps holds does not count.
//
// Between the jaws, in the tool frame (forceps.h: x from the tip to the hinge, the jaws
// opening in ±y): a node with the hinge ahead of it (x ≤ L), no nearer the tip than the open
// tips (x ≥ L − L cos θ), between the jaw axes (|y| < (L − x) tan θ) and within the capsules'
// width there (|z| < their radius): the jaw meshes' gripping faces lie on their axes, so that
// space is free. θ is the opening of the frame before (Forceps::closedFrom): closing jaws
// keep clear of what they swept, and opening jaws do not count the turns their axes have just
// passed as between them. Closed jaws (θ = 0) have nothing between them.
//
// Units: mm.

#include "microsim/sim/suture/suture_contact.h"
#include "microsim/sim/tools/forceps.h"

#include <vector>

namespace microsim::sim {

/// Appends the jaws of `forceps` for the chain at positions x (a needle lying free on nodes
/// 0..swage, −1 without one, then the thread, of radius `threadRadius`, mm; header essay).
void appendThreadJawObstacles(const tools::Forceps& forceps, const Points& x, int swage, double threadRadius,
                              std::vector<suture::Capsule>& out);

}  // namespace microsim::sim
