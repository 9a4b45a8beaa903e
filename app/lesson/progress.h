#pragma once
// A lesson's steps against what has happened so far in an attempt. Steps tick off in order:
// step i counts as done only once steps 0..i-1 are, and then as soon as its condition holds
// on everything that happened since the attempt began (a grab before step 1 was reached still
// counts for step 2).
//
// Facts, from the scene's events and pierces and the tissue's displacement:
//   grab      the largest GrabTissue event's node count;
//   stretch   the largest distance any tissue node has moved from where it started (mm);
//   pierces   PierceEntry events (the needle entering a wall, from either side);
//   crossings the needle crossed the gap: entered one end of a severed vessel from its lumen
//             having last left the other end (a needle that leaves the near end's lumen
//             through its own back wall has not crossed: a back-wall catch);
//   stitches  completed passes: the needle went in and out of one end of a severed vessel
//             and then in and out of the other; a new stitch begins with the next entry;
//   target i  some pierce point (entry or exit) lies within the tolerance of guides[i];
//   empty grasp  the hand whose latest grasp (either hand's GrabTissue, GripSuture or
//             GraspEmpty) closed on nothing, or −1: for the page to say so until a grasp holds;
//   throws    ThrowFormed events (a throw laid in the thread);
//   knots     KnotTightened events (a knot pulled tight);
//   cuts      ThreadCut events (the scissors cut the thread), and the latest one's cut-end
//             length (mm; −1 when neither side of the cut reaches a pierce); tails, the cuts
//             that left a cut end on a stitch (length ≥ 0);
//   too short the thread the needle kept at the latest ThreadTooShort (mm), or −1: a cut left
//             it too short to tie, and no thread grows back.

#include "lesson/lesson.h"

#include "microsim/sim/scene/scene_events.h"

#include <vector>

namespace microsim::lesson {

struct AttemptFacts {
  int maxGrabNodes = 0;
  double maxDisplacementMm = 0.0;  ///< mm
  int pierceEntries = 0;
  int crossings = 0;
  int stitches = 0;
  std::vector<sim::PierceEvent> pierces;
  int emptyGraspHand = -1;  ///< see "empty grasp" above
  int throwsFormed = 0;           ///< see "throws" above
  int knotsTightened = 0;         ///< see "knots" above
  int threadCuts = 0;             ///< see "cuts" above
  int tailsCut = 0;               ///< see "cuts" above
  double lastCutEndMm = -1.0;     ///< mm, or −1 (see "cuts")
  double threadTooShortMm = -1.0; ///< mm, or −1 (see "too short")
};

/// Facts from the scene's events and pierces; `maxDisplacementMm` is the caller's (the
/// snapshots carry the positions).
AttemptFacts collectFacts(const std::vector<sim::SceneEvent>& events,
                          const std::vector<sim::PierceEvent>& pierces, double maxDisplacementMm);

/// Completed stitches in a pierce sequence (see the header comment).
int countStitches(const std::vector<sim::PierceEvent>& pierces);
/// Gap crossings in a pierce sequence (see the header comment).
int countCrossings(const std::vector<sim::PierceEvent>& pierces);

bool conditionMet(const Condition& condition, const Lesson& lesson, const AttemptFacts& facts);

/// How many steps are done, in order (0..steps.size()).
int stepsDone(const Lesson& lesson, const AttemptFacts& facts);

/// Which guides have been hit by some pierce within `toleranceMm`.
std::vector<bool> guidesHit(const Lesson& lesson, const AttemptFacts& facts, double toleranceMm);

}  // namespace microsim::lesson
