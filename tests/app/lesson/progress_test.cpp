#include "lesson/progress.h"

#include "microsim/sim/scene/recording.h"
#include "microsim/sim/scene/scene.h"

#include <gtest/gtest.h>

namespace microsim::lesson {
namespace {

const std::string kSource = MICROSIM_SOURCE_DIR;

sim::SceneEvent sceneEvent(sim::SceneEventKind kind, int hand, double value = 0.0) {
  sim::SceneEvent e;
  e.kind = kind;
  e.hand = hand;
  e.value = value;
  return e;
}

sim::PierceEvent pierce(int end, bool entry) {
  sim::PierceEvent p;
  p.end = end;
  p.entry = entry;
  return p;
}

TEST(LessonProgress, CountsAStitchOnlyWhenBothEndsArePassed) {
  EXPECT_EQ(countStitches({}), 0);
  EXPECT_EQ(countStitches({pierce(0, true), pierce(0, false)}), 0);
  EXPECT_EQ(countStitches({pierce(0, true), pierce(0, false), pierce(1, true), pierce(1, false)}), 1);
  // an exit without its entry is no pass; other tissue is ignored
  EXPECT_EQ(countStitches({pierce(0, false), pierce(1, true), pierce(1, false), pierce(-1, true)}), 0);
  EXPECT_EQ(countStitches({pierce(0, true), pierce(0, false), pierce(1, true), pierce(1, false),
                           pierce(1, true), pierce(1, false), pierce(0, true), pierce(0, false)}),
            2);
}

sim::PierceEvent pierce(int end, bool entry, sim::VesselSurface surface) {
  sim::PierceEvent p = pierce(end, entry);
  p.surface = surface;
  return p;
}

TEST(LessonProgress, AGapIsCrossedByEnteringOneEndFromItsLumenAfterLeavingTheOther) {
  using S = sim::VesselSurface;
  // a stitch: out of end 0's lumen, into end 1's
  EXPECT_EQ(countCrossings({pierce(0, true, S::Outer), pierce(0, false, S::Inner),
                            pierce(1, true, S::Inner), pierce(1, false, S::Outer)}),
            1);
  // a back-wall catch: out of end 0's front wall into its own back wall
  EXPECT_EQ(countCrossings({pierce(0, true, S::Outer), pierce(0, false, S::Inner),
                            pierce(0, true, S::Inner), pierce(0, false, S::Outer)}),
            0);
  // end 1 entered from outside is no crossing; nor is an entry with no exit before it
  EXPECT_EQ(countCrossings(
                {pierce(0, true, S::Outer), pierce(0, false, S::Inner), pierce(1, true, S::Outer)}),
            0);
  EXPECT_EQ(countCrossings({pierce(1, true, S::Inner)}), 0);
  // each crossing needs its own exit: two stitches the other way round cross twice
  EXPECT_EQ(countCrossings({pierce(1, true, S::Outer), pierce(1, false, S::Inner),
                            pierce(0, true, S::Inner), pierce(0, false, S::Outer),
                            pierce(1, true, S::Outer), pierce(1, false, S::Inner),
                            pierce(0, true, S::Inner)}),
            2);
}

Lesson twoSteps() {
  Lesson l;
  l.steps.push_back({{}, {ConditionKind::Grab, 3, 0.0}});
  l.steps.push_back({{}, {ConditionKind::Stretch, 1, 0.3}});
  return l;
}

TEST(LessonProgress, StepsTickOffInOrder) {
  const Lesson l = twoSteps();
  AttemptFacts facts;
  EXPECT_EQ(stepsDone(l, facts), 0);
  facts.maxDisplacementMm = 0.5;  // the stretch alone does not skip the grab
  EXPECT_EQ(stepsDone(l, facts), 0);
  facts.maxGrabNodes = 2;
  EXPECT_EQ(stepsDone(l, facts), 0);
  facts.maxGrabNodes = 3;
  EXPECT_EQ(stepsDone(l, facts), 2);
}

TEST(LessonProgress, FactsComeFromEvents) {
  sim::SceneEvent grab;
  grab.kind = sim::SceneEventKind::GrabTissue;
  grab.count = 4;
  sim::SceneEvent entry;
  entry.kind = sim::SceneEventKind::PierceEntry;
  const AttemptFacts f = collectFacts({grab, entry, entry}, {pierce(0, true)}, 0.2);
  EXPECT_EQ(f.maxGrabNodes, 4);
  EXPECT_EQ(f.pierceEntries, 2);
  EXPECT_DOUBLE_EQ(f.maxDisplacementMm, 0.2);
  EXPECT_EQ(f.stitches, 0);
}

TEST(LessonProgress, AnEmptyGraspIsAFactUntilAGraspHolds) {
  const auto event = [](sim::SceneEventKind kind, int hand) { return sceneEvent(kind, hand); };
  using K = sim::SceneEventKind;
  EXPECT_EQ(collectFacts({}, {}, 0.0).emptyGraspHand, -1);
  EXPECT_EQ(collectFacts({event(K::GraspEmpty, 1)}, {}, 0.0).emptyGraspHand, 1);
  // a release or a pierce does not clear it; the other hand's grasp on nothing replaces it
  EXPECT_EQ(collectFacts({event(K::GraspEmpty, 1), event(K::ReleaseTissue, 0), event(K::PierceEntry, -1)}, {}, 0.0)
                .emptyGraspHand,
            1);
  EXPECT_EQ(collectFacts({event(K::GraspEmpty, 1), event(K::GraspEmpty, 0)}, {}, 0.0).emptyGraspHand, 0);
  // a grasp that holds, tissue or suture, by either hand, clears it
  EXPECT_EQ(collectFacts({event(K::GraspEmpty, 1), event(K::GrabTissue, 0)}, {}, 0.0).emptyGraspHand, -1);
  EXPECT_EQ(collectFacts({event(K::GraspEmpty, 0), event(K::GripSuture, 0)}, {}, 0.0).emptyGraspHand, -1);
}

TEST(LessonProgress, CutsCountAndTheLatestCutEndAndTooShortAreKept) {
  const auto cutEvent = [](sim::SceneEventKind kind, double value) { return sceneEvent(kind, 1, value); };
  using K = sim::SceneEventKind;
  const AttemptFacts none = collectFacts({}, {}, 0.0);
  EXPECT_EQ(none.threadCuts, 0);
  EXPECT_EQ(none.lastCutEndMm, -1.0);
  EXPECT_EQ(none.threadTooShortMm, -1.0);
  // two cuts: the latest one's end; an unanchored cut (−1) is kept as it is
  const AttemptFacts two = collectFacts({cutEvent(K::ThreadCut, 2.5), cutEvent(K::ThreadCut, 0.8)}, {}, 0.0);
  EXPECT_EQ(two.threadCuts, 2);
  EXPECT_EQ(two.lastCutEndMm, 0.8);
  EXPECT_EQ(two.threadTooShortMm, -1.0);
  const AttemptFacts loose =
      collectFacts({cutEvent(K::ThreadCut, -1.0), cutEvent(K::ThreadTooShort, 1.4), cutEvent(K::GrabTissue, 0.0)}, {}, 0.0);
  EXPECT_EQ(loose.threadCuts, 1);
  EXPECT_EQ(loose.lastCutEndMm, -1.0);
  EXPECT_EQ(loose.threadTooShortMm, 1.4);
}

TEST(LessonProgress, AKnotStepWaitsForAKnotPulledTightAndACutStepForTails) {
  const auto event = [](sim::SceneEventKind kind, double value) { return sceneEvent(kind, -1, value); };
  using K = sim::SceneEventKind;
  Lesson l;
  l.steps.push_back({{}, {ConditionKind::Knots, 1, 0.0}});
  l.steps.push_back({{}, {ConditionKind::Cuts, 2, 0.0}});
  // a throw formed is not yet a knot; trimming loose thread (cut end −1) is not a tail
  EXPECT_EQ(stepsDone(l, collectFacts({event(K::ThrowFormed, 0.0)}, {}, 0.0)), 0);
  Lesson throws;
  throws.steps.push_back({{}, {ConditionKind::Throws, 2, 0.0}});
  EXPECT_EQ(stepsDone(throws, collectFacts({event(K::ThrowFormed, 0.0)}, {}, 0.0)), 0);
  EXPECT_EQ(stepsDone(throws, collectFacts({event(K::ThrowFormed, 0.0), event(K::ThrowFormed, 0.0)}, {}, 0.0)), 1);
  const AttemptFacts tied = collectFacts({event(K::ThrowFormed, 0.0), event(K::KnotTightened, 900.0)}, {}, 0.0);
  EXPECT_EQ(tied.knotsTightened, 1);
  EXPECT_EQ(stepsDone(l, tied), 1);
  const AttemptFacts trimmed =
      collectFacts({event(K::KnotTightened, 900.0), event(K::ThreadCut, 1.1), event(K::ThreadCut, -1.0)}, {}, 0.0);
  EXPECT_EQ(trimmed.threadCuts, 2);
  EXPECT_EQ(trimmed.tailsCut, 1);
  EXPECT_EQ(stepsDone(l, trimmed), 1);
  const AttemptFacts cut =
      collectFacts({event(K::KnotTightened, 900.0), event(K::ThreadCut, 1.1), event(K::ThreadCut, 0.9)}, {}, 0.0);
  EXPECT_EQ(stepsDone(l, cut), 2);
  // tails cut before any knot do not tick the cut step off: steps go in order
  EXPECT_EQ(stepsDone(l, collectFacts({event(K::ThreadCut, 1.1), event(K::ThreadCut, 0.9)}, {}, 0.0)), 0);
}

// the shipped stitch recording completes lesson 02, and lesson 03's stitch steps, not its knot
// and cut (it ties no knot); their targets sit where it pierces
TEST(LessonProgress, TheShippedStitchCompletesLessonTwoAndTheStitchOfLessonThree) {
  sim::Recording recording;
  ASSERT_TRUE(sim::readRecording(kSource + "/resources/recordings/stitch.msrec", recording).ok());
  for (const char* id : {"02_needle_entry", "03_single_stitch"}) {
    const auto loaded = loadLesson(QStringLiteral(MICROSIM_SOURCE_DIR "/resources/lessons/%1.json").arg(QLatin1String(id)));
    ASSERT_TRUE(std::holds_alternative<Lesson>(loaded)) << std::get<LessonError>(loaded).field.toStdString();
    const Lesson& lesson = std::get<Lesson>(loaded);
    auto opened = sim::openScene(lesson.scenePath.toStdString());
    ASSERT_TRUE(std::holds_alternative<std::unique_ptr<sim::Scene>>(opened));
    sim::Scene& scene = *std::get<std::unique_ptr<sim::Scene>>(opened);
    int doneBeforeEnd = 0;
    for (std::size_t i = 0; i < recording.frames.size(); ++i) {
      scene.step(recording.frames[i]);
      if (i + 1 == 90)  // 0.9 s, before the first pierce at 1.02 s
        doneBeforeEnd = stepsDone(lesson, collectFacts(scene.events(), scene.pierces(), 0.0));
    }
    const AttemptFacts facts = collectFacts(scene.events(), scene.pierces(), 0.0);
    EXPECT_EQ(doneBeforeEnd, 0) << id;
    const bool knotted = std::string(id) == "03_single_stitch";
    EXPECT_EQ(stepsDone(lesson, facts), static_cast<int>(lesson.steps.size()) - (knotted ? 2 : 0)) << id;
    if (knotted) {
      EXPECT_EQ(lesson.steps[3].success.kind, ConditionKind::Knots);
    }
    for (bool hit : guidesHit(lesson, facts, 0.1)) EXPECT_TRUE(hit) << id;
  }
}

// the shipped back-wall catch pierces twice but never crosses the gap: lesson 3 ticks its
// first step (the near end pierced) and stops at "enter the far end from the lumen"
TEST(LessonProgress, TheShippedBackWallCatchDoesNotCrossTheGapOfLessonThree) {
  sim::Recording recording;
  ASSERT_TRUE(
      sim::readRecording(kSource + "/resources/recordings/back_wall_catch.msrec", recording).ok());
  const auto loaded =
      loadLesson(QStringLiteral(MICROSIM_SOURCE_DIR "/resources/lessons/03_single_stitch.json"));
  ASSERT_TRUE(std::holds_alternative<Lesson>(loaded));
  const Lesson& lesson = std::get<Lesson>(loaded);
  auto opened = sim::openScene(lesson.scenePath.toStdString());
  ASSERT_TRUE(std::holds_alternative<std::unique_ptr<sim::Scene>>(opened));
  sim::Scene& scene = *std::get<std::unique_ptr<sim::Scene>>(opened);
  for (const sim::InputFrame& f : recording.frames) scene.step(f);
  const AttemptFacts facts = collectFacts(scene.events(), scene.pierces(), 0.0);
  EXPECT_EQ(facts.pierceEntries, 2);
  EXPECT_EQ(facts.crossings, 0);
  EXPECT_EQ(facts.stitches, 0);
  EXPECT_EQ(lesson.steps[1].success.kind, ConditionKind::Crossings);
  EXPECT_EQ(stepsDone(lesson, facts), 1);
}

}  // namespace
}  // namespace microsim::lesson
