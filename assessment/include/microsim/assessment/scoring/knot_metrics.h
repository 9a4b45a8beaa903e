#pragma once
// The knots an attempt tied and the thread it cut (issue #19; MARS10's "knot tying" and
// "cut-end length"), read from the scene's knot and scissors events alone, so an attempt
// replayed from a recording or written by hand in a test is judged alike.
//
//   tightened   KnotTightened events: a knot pulled tight (suture/knot_tracker.h).
//   secure      tightened knots that lock: a square knot or a surgeon's knot (a double throw,
//               then a throw of the other hand) of at least two throws, not followed by a
//               KnotSlipped before the next knot was tightened. A granny, a slip knot, a
//               single throw or a knot the recogniser cannot name does not lock: the tracker
//               reports its slip when it runs, and a rubric weighs it as not secure anyway.
//   slipped     KnotSlipped events: a tightened knot lost throws or ran along the thread.
//   throws      the throws of each tightened knot, their mean (NaN when none was tightened).
//   cuts        ThreadCut events that left a cut end on a stitch (value ≥ 0); a cut where
//               neither side reaches a pierce (value −1) trims loose thread and is not a tail.
//   cut end     the cut-end length of those cuts (mm), their mean and their longest.
//
// Units: millimetres.

#include "microsim/sim/scene/scene_events.h"

#include <limits>
#include <vector>

namespace microsim::assessment {

struct KnotSummary {
  int tightened = 0;
  int secure = 0;
  int slipped = 0;
  double meanThrows = std::numeric_limits<double>::quiet_NaN();
  int cuts = 0;
  double meanCutEndMm = std::numeric_limits<double>::quiet_NaN();     ///< mm
  double longestCutEndMm = std::numeric_limits<double>::quiet_NaN();  ///< mm
};

/// True for the knot types that lock when pulled tight: square and surgeon's.
bool knotTypeLocks(sim::suture::KnotType type);

/// The summary above, from an attempt's events in order.
KnotSummary knotSummary(const std::vector<sim::SceneEvent>& events);

}  // namespace microsim::assessment
