// The replay timeline's marks from scene events: kinds, lanes and positions.
#include "gui/review/replay_marks.h"

#include <gtest/gtest.h>

namespace microsim::gui {
namespace {

sim::SceneEvent timedEvent(sim::SceneEventKind kind, int step, int hand = -1, int index = -1) {
  sim::SceneEvent e;
  e.kind = kind;
  e.step = step;
  e.time = 0.01 * (step + 1);
  e.hand = hand;
  e.index = index;
  return e;
}

TEST(ReplayMarks, EachEventIsMarkedAtThePositionThatShowsIt) {
  using K = sim::SceneEventKind;
  const std::vector<ReplayMark> marks = replayMarks({
      timedEvent(K::GripSuture, 4, 1),
      timedEvent(K::InputRejected, 5),
      timedEvent(K::PierceEntry, 9, -1, 0),
      timedEvent(K::PierceExit, 30, -1, 1),
      timedEvent(K::ReleaseTissue, 31, 0),
      timedEvent(K::TissueTear, 40),
      timedEvent(K::GraspEmpty, 41, 0),
  });
  ASSERT_EQ(marks.size(), 6u);  // the rejected frame is not marked
  EXPECT_EQ(marks[0].kind, ReplayMarkKind::Grasp);
  EXPECT_EQ(marks[0].position, 5);
  EXPECT_EQ(marks[0].hand, 1);
  EXPECT_EQ(marks[0].pierce, -1);
  EXPECT_EQ(marks[1].kind, ReplayMarkKind::PierceEntry);
  EXPECT_EQ(marks[1].position, 10);
  EXPECT_DOUBLE_EQ(marks[1].time, 0.10);
  EXPECT_EQ(marks[1].pierce, 0);
  EXPECT_EQ(marks[2].kind, ReplayMarkKind::PierceExit);
  EXPECT_EQ(marks[2].pierce, 0);  // the exit of the first pass
  EXPECT_EQ(marks[3].kind, ReplayMarkKind::Release);
  EXPECT_EQ(marks[4].kind, ReplayMarkKind::Tear);
  EXPECT_EQ(marks[5].kind, ReplayMarkKind::GraspEmpty);
}

TEST(ReplayMarks, CrossingsAreNumberedByThePassTheyBelongTo) {
  using K = sim::SceneEventKind;
  const std::vector<ReplayMark> marks = replayMarks({
      timedEvent(K::PierceEntry, 10, -1, 0),
      timedEvent(K::PierceExit, 20, -1, 1),
      timedEvent(K::PierceEntry, 30, -1, 2),
      timedEvent(K::PierceExit, 40, -1, 3),
      timedEvent(K::SuturePulledOut, 50, -1, 1),
      timedEvent(K::PierceReleased, 60, -1, 2),
  });
  ASSERT_EQ(marks.size(), 6u);
  EXPECT_EQ(marks[0].pierce, 0);
  EXPECT_EQ(marks[1].pierce, 0);
  EXPECT_EQ(marks[2].pierce, 1);
  EXPECT_EQ(marks[3].pierce, 1);
  EXPECT_EQ(marks[4].pierce, 0);  // the first pass's exit
  EXPECT_EQ(marks[5].pierce, 1);  // the second pass's entry
}

TEST(ReplayMarks, AKnotIsMarkedWhenItIsPulledTightAndWhenItSlipsNotThrowByThrow) {
  using K = sim::SceneEventKind;
  const std::vector<ReplayMark> marks = replayMarks({
      timedEvent(K::ThrowFormed, 100, -1, 0),
      timedEvent(K::ThrowFormed, 140, -1, 1),
      timedEvent(K::KnotTightened, 150),
      timedEvent(K::KnotSlipped, 200),
  });
  ASSERT_EQ(marks.size(), 2u);
  EXPECT_EQ(marks[0].kind, ReplayMarkKind::Knot);
  EXPECT_EQ(marks[0].position, 151);
  EXPECT_EQ(marks[1].kind, ReplayMarkKind::KnotSlipped);
  EXPECT_EQ(marks[1].position, 201);
}

TEST(ReplayMarks, LanesGroupWhatIsLookedForTogether) {
  EXPECT_EQ(laneOf(ReplayMarkKind::PierceEntry), ReplayLane::Pierces);
  EXPECT_EQ(laneOf(ReplayMarkKind::PierceExit), ReplayLane::Pierces);
  EXPECT_EQ(laneOf(ReplayMarkKind::Grasp), ReplayLane::Grasps);
  EXPECT_EQ(laneOf(ReplayMarkKind::Release), ReplayLane::Grasps);
  EXPECT_EQ(laneOf(ReplayMarkKind::OverStretch), ReplayLane::Tissue);
  EXPECT_EQ(laneOf(ReplayMarkKind::Tear), ReplayLane::Tissue);
  EXPECT_EQ(laneOf(ReplayMarkKind::Cut), ReplayLane::Tissue);
  EXPECT_EQ(laneOf(ReplayMarkKind::Knot), ReplayLane::Knots);
  EXPECT_EQ(laneOf(ReplayMarkKind::KnotSlipped), ReplayLane::Knots);
  EXPECT_EQ(laneOf(ReplayMarkKind::GraspEmpty), ReplayLane::Errors);
  EXPECT_EQ(laneOf(ReplayMarkKind::SutureBreak), ReplayLane::Errors);
  EXPECT_EQ(laneOf(ReplayMarkKind::SuturePulledOut), ReplayLane::Errors);
  EXPECT_EQ(laneOf(ReplayMarkKind::PierceReleased), ReplayLane::Errors);
}

}  // namespace
}  // namespace microsim::gui
