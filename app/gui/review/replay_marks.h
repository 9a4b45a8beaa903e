#pragma once
// The replay timeline's marks: which of an attempt's scene events are shown, on which lane,
// and at which position of the replay (ReplayPlayer's positions: frames stepped).
//
// A pure mapping from the engine's events, tested without widgets. Lanes group what an
// instructor looks for together: the needle's passages through the walls, what the forceps
// held, what happened to the tissue, the knot and the thread, and errors. A knot is marked when
// it is pulled tight and when it slips; the throws that form it are not (they come in quick
// succession while it is tied, and the tightened knot names them).

#include "microsim/sim/scene/scene_events.h"

#include <array>
#include <vector>

namespace microsim::gui {

enum class ReplayMarkKind {
  PierceEntry,
  PierceExit,
  Grasp,        ///< a forceps took tissue or the suture
  Release,      ///< it let go
  OverStretch,  ///< a tissue link stretched beyond the scene's limit
  Tear,         ///< links torn
  Cut,          ///< the scalpel cut links
  Knot,         ///< a knot pulled tight
  KnotSlipped,  ///< a tightened knot slipped
  ThreadCut,    ///< the scissors cut the thread
  ThreadTooShort,  ///< a cut left the needle too little thread to tie
  GraspEmpty,   ///< a forceps closed on nothing
  SutureBreak,
  SuturePulledOut,
  PierceReleased,  ///< the needle left a pierce before the thread reached it
};

enum class ReplayLane { Pierces, Grasps, Tissue, Knots, Errors };
inline constexpr std::array kReplayLanes{ReplayLane::Pierces, ReplayLane::Grasps, ReplayLane::Tissue,
                                         ReplayLane::Knots, ReplayLane::Errors};

struct ReplayMark {
  ReplayMarkKind kind = ReplayMarkKind::PierceEntry;
  /// the replay position at which it has happened: the step it happened in, plus one
  int position = 0;
  double time = 0.0;  ///< s, scene time
  int hand = -1;      ///< 0 left, 1 right, -1 none
  /// pierce kinds: which pass of the needle through a wall (0-based, in the order of their
  /// entries); an exit, a release or a pull-out belongs to the pass its entry began
  int pierce = -1;
};

ReplayLane laneOf(ReplayMarkKind kind);

/// The marks of `events` in their order; rejected input frames are not marked (the frame
/// before is used again: nothing happens to see).
std::vector<ReplayMark> replayMarks(const std::vector<sim::SceneEvent>& events);

}  // namespace microsim::gui
