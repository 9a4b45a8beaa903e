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
// Turns wound on the jaws. A run of consecutive thread nodes (not the needle, not the run the
// jaws hold) between tip and hinge, each outside the jaws' hull (their capsules and the slab
// between them: suture_contact.h, Sleeve; pressed in by no more than 0.03 mm) and no more
// than 0.06 mm off it, that crosses at least four quadrant boundaries about the tool's axis
// (more than three quarters of a turn; a link across the axis, two at once, goes through the
// jaws and ends the run) is wound on them. The count uses signs only, so it cannot differ
// between machines' maths libraries. A wound run is kept in a shell 0.03 mm loose round the
// hull by a sleeve, the jaws do not take it when they close (they take what lies between
// them: the tail), a hole beside it draws no thread through it from beyond it
// (suture_constraints.h), and a hole that slides does not carry it (suture_solver.cpp).
// Nothing is remembered from frame to frame: a run is wound while it is, and comes off where
// the shell ends, past the tips, when the jaws are drawn back out of it.
//
// Units: mm.

#include "microsim/sim/suture/suture_solver.h"
#include "microsim/sim/tools/forceps.h"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace microsim::sim {

/// The chain as the jaws meet it.
struct ThreadNearJaws {
  const Points& x;
  std::span<const std::uint8_t> alive;  ///< per link
  int freeNeedleSwage = -1;             ///< a needle lying free on nodes 0..swage; −1: none
  int firstThreadNode = 0;              ///< nodes before it are the needle's
  double radius = 0.0;                  ///< the thread's
};

/// Appends the jaws of `forceps` (capsules, and a sleeve per wound run) for the chain
/// (header essay).
void appendThreadJawObstacles(const tools::Forceps& forceps, const ThreadNearJaws& thread,
                              suture::SutureWorld& world);

/// The runs of thread wound on the jaws of `forceps`, [first, last] nodes (header essay).
std::vector<std::array<int, 2>> threadWoundOnJaws(const tools::Forceps& forceps,
                                                  const ThreadNearJaws& thread);

}  // namespace microsim::sim
