#include "gui/review/replay_marks.h"

#include <algorithm>
#include <map>
#include <optional>

namespace microsim::gui {

namespace {

std::optional<ReplayMarkKind> markKindOf(sim::SceneEventKind kind) {
  using K = sim::SceneEventKind;
  switch (kind) {
    case K::GrabTissue:
    case K::GripSuture: return ReplayMarkKind::Grasp;
    case K::ReleaseTissue:
    case K::ReleaseSuture: return ReplayMarkKind::Release;
    case K::PierceEntry: return ReplayMarkKind::PierceEntry;
    case K::PierceExit: return ReplayMarkKind::PierceExit;
    case K::Cut: return ReplayMarkKind::Cut;
    case K::SutureBreak: return ReplayMarkKind::SutureBreak;
    case K::SuturePulledOut: return ReplayMarkKind::SuturePulledOut;
    case K::PierceReleased: return ReplayMarkKind::PierceReleased;
    case K::InputRejected: return std::nullopt;
    case K::TissueOverStretch: return ReplayMarkKind::OverStretch;
    case K::TissueTear: return ReplayMarkKind::Tear;
    case K::GraspEmpty: return ReplayMarkKind::GraspEmpty;
    case K::ThreadCut: return ReplayMarkKind::ThreadCut;
    case K::ThreadTooShort: return ReplayMarkKind::ThreadTooShort;
    case K::ThrowFormed: return std::nullopt;
    case K::KnotTightened: return ReplayMarkKind::Knot;
    case K::KnotSlipped: return ReplayMarkKind::KnotSlipped;
  }
  return std::nullopt;
}

bool isPierceKind(sim::SceneEventKind kind) {
  using K = sim::SceneEventKind;
  return kind == K::PierceEntry || kind == K::PierceExit || kind == K::SuturePulledOut || kind == K::PierceReleased;
}

}  // namespace

ReplayLane laneOf(ReplayMarkKind kind) {
  switch (kind) {
    case ReplayMarkKind::PierceEntry:
    case ReplayMarkKind::PierceExit: return ReplayLane::Pierces;
    case ReplayMarkKind::Grasp:
    case ReplayMarkKind::Release: return ReplayLane::Grasps;
    case ReplayMarkKind::OverStretch:
    case ReplayMarkKind::Tear:
    case ReplayMarkKind::Cut: return ReplayLane::Tissue;
    case ReplayMarkKind::Knot:
    case ReplayMarkKind::KnotSlipped:
    case ReplayMarkKind::ThreadCut: return ReplayLane::Knots;
    case ReplayMarkKind::ThreadTooShort:
    case ReplayMarkKind::GraspEmpty:
    case ReplayMarkKind::SutureBreak:
    case ReplayMarkKind::SuturePulledOut:
    case ReplayMarkKind::PierceReleased: return ReplayLane::Errors;
  }
  return ReplayLane::Errors;
}

std::vector<ReplayMark> replayMarks(const std::vector<sim::SceneEvent>& events) {
  std::vector<ReplayMark> marks;
  // the engine numbers each crossing; a pass is numbered by its entry, and the crossings
  // after an entry (its exit, a release, a pull-out) belong to that pass
  std::map<int, int> passOfCrossing;
  int passes = 0;
  for (const sim::SceneEvent& e : events) {
    const std::optional<ReplayMarkKind> kind = markKindOf(e.kind);
    if (!kind) continue;
    int pass = -1;
    if (e.kind == sim::SceneEventKind::PierceEntry) {
      pass = passes++;
      passOfCrossing[e.index] = pass;
    } else if (isPierceKind(e.kind)) {
      const auto known = passOfCrossing.find(e.index);
      pass = known != passOfCrossing.end() ? known->second : std::max(0, passes - 1);
      passOfCrossing.emplace(e.index, pass);
    }
    marks.push_back({*kind, e.step + 1, e.time, e.hand, pass});
  }
  return marks;
}

}  // namespace microsim::gui
