#include "lesson/progress.h"

#include <algorithm>
#include <array>

namespace microsim::lesson {

int countStitches(const std::vector<sim::PierceEvent>& pierces) {
  int stitches = 0;
  std::array<bool, 2> entered{};
  std::array<bool, 2> passed{};
  for (const sim::PierceEvent& p : pierces) {
    if (p.end != 0 && p.end != 1) continue;
    const auto end = static_cast<std::size_t>(p.end);
    if (p.entry) {
      entered[end] = true;
    } else if (entered[end]) {
      passed[end] = true;
    }
    if (passed[0] && passed[1]) {
      ++stitches;
      entered = {};
      passed = {};
    }
  }
  return stitches;
}

int countCrossings(const std::vector<sim::PierceEvent>& pierces) {
  int crossings = 0;
  int leftEnd = -1;  // the end the needle last came out of
  for (const sim::PierceEvent& p : pierces) {
    if (p.end != 0 && p.end != 1) continue;
    if (!p.entry) {
      leftEnd = p.end;
    } else if (p.surface == sim::VesselSurface::Inner && leftEnd == 1 - p.end) {
      ++crossings;
      leftEnd = -1;
    }
  }
  return crossings;
}

AttemptFacts collectFacts(const std::vector<sim::SceneEvent>& events,
                          const std::vector<sim::PierceEvent>& pierces, double maxDisplacementMm) {
  AttemptFacts facts;
  facts.maxDisplacementMm = maxDisplacementMm;
  for (const sim::SceneEvent& e : events) {
    if (e.kind == sim::SceneEventKind::GrabTissue) facts.maxGrabNodes = std::max(facts.maxGrabNodes, e.count);
    if (e.kind == sim::SceneEventKind::PierceEntry) ++facts.pierceEntries;
    if (e.kind == sim::SceneEventKind::GraspEmpty) facts.emptyGraspHand = e.hand;
    if (e.kind == sim::SceneEventKind::GrabTissue || e.kind == sim::SceneEventKind::GripSuture)
      facts.emptyGraspHand = -1;
    if (e.kind == sim::SceneEventKind::ThrowFormed) ++facts.throwsFormed;
    if (e.kind == sim::SceneEventKind::KnotTightened) ++facts.knotsTightened;
    if (e.kind == sim::SceneEventKind::ThreadCut) {
      ++facts.threadCuts;
      facts.tailsCut += e.value >= 0.0 ? 1 : 0;
      facts.lastCutEndMm = e.value;
    }
    if (e.kind == sim::SceneEventKind::ThreadTooShort) facts.threadTooShortMm = e.value;
  }
  facts.stitches = countStitches(pierces);
  facts.crossings = countCrossings(pierces);
  facts.pierces = pierces;
  return facts;
}

namespace {

bool targetHit(const Guide& guide, const AttemptFacts& facts, double toleranceMm) {
  return std::any_of(facts.pierces.begin(), facts.pierces.end(), [&](const sim::PierceEvent& p) {
    return (p.restPoint - guide.target).norm() <= toleranceMm;
  });
}

}  // namespace

bool conditionMet(const Condition& condition, const Lesson& lesson, const AttemptFacts& facts) {
  switch (condition.kind) {
    case ConditionKind::Grab: return facts.maxGrabNodes >= condition.count;
    case ConditionKind::Stretch: return facts.maxDisplacementMm >= condition.millimetres;
    case ConditionKind::Pierces: return facts.pierceEntries >= condition.count;
    case ConditionKind::Crossings:
      return facts.crossings >= condition.count;
    case ConditionKind::Stitches: return facts.stitches >= condition.count;
    case ConditionKind::Throws: return facts.throwsFormed >= condition.count;
    case ConditionKind::Knots: return facts.knotsTightened >= condition.count;
    case ConditionKind::Cuts: return facts.tailsCut >= condition.count;
    case ConditionKind::Target:
      return condition.count >= 0 && condition.count < static_cast<int>(lesson.guides.size()) &&
             targetHit(lesson.guides[static_cast<std::size_t>(condition.count)], facts, condition.millimetres);
  }
  return false;
}

int stepsDone(const Lesson& lesson, const AttemptFacts& facts) {
  int done = 0;
  for (const Step& step : lesson.steps) {
    if (!conditionMet(step.success, lesson, facts)) break;
    ++done;
  }
  return done;
}

std::vector<bool> guidesHit(const Lesson& lesson, const AttemptFacts& facts, double toleranceMm) {
  std::vector<bool> hit;
  hit.reserve(lesson.guides.size());
  for (const Guide& g : lesson.guides) hit.push_back(targetHit(g, facts, toleranceMm));
  return hit;
}

}  // namespace microsim::lesson
