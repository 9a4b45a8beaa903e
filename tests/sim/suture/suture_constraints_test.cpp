// Pierces along the thread (suture_constraints.h): an active pierce stays on the thread, a
// passive one is released when the needle leaves it, and no two pierces change their order.
#include "microsim/sim/suture/suture_constraints.h"
#include "microsim/sim/suture/suture_solver.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

namespace microsim::sim::suture {
namespace {

// the default curved needle (radius 1 mm, 8 links; nodes 0..8, swage 8) and 50 thread links
// of 0.1 mm, laid out in the needle frame: the needle's circle has its centre at (0, 1, 0)
SutureModel needleAndThread() {
  SutureDef d;
  d.links = 58;
  d.length = 5.0;
  return SutureModel(d);
}

Pierce pierceThrough(int node, const Vec3& point) {
  Pierce p;
  p.face = 0;
  p.barycentric = Vec3(1, 0, 0);
  p.node = node;
  p.point = point;
  return p;
}

int slideAtDefaultTolerance(const SutureModel& m, SutureState& s, std::span<const Grip> grips,
                            std::vector<SutureEvent>& events) {
  return slidePierces(m, s, grips, SutureStepParams{}.slideTolerance, events);
}

TEST(SutureGrips, AGripBetweenTwoNodesHoldsBothAndOnTheNeedleHoldsTheNeedle) {
  const SutureModel m = needleAndThread();
  const SutureState s = SutureState::laidOut(m);
  const Piece whole{0, m.nodeCount() - 1};
  Grip g;
  g.node = 30;
  g.fraction = 0.5;
  g.position = Vec3(9, 9, 9);
  const std::vector<ChainConstraint> between =
      pieceConstraints(m, s, std::span<const Grip>(&g, 1), whole);
  ASSERT_EQ(between.size(), 2u);
  EXPECT_EQ(between[0].node, 30);
  EXPECT_EQ(between[1].node, 31);
  EXPECT_TRUE(between[0].hard && between[1].hard);
  EXPECT_EQ(between[0].position, Vec3(s.x.col(30)));
  EXPECT_EQ(between[1].position, Vec3(s.x.col(31)));
  EXPECT_EQ(gripPoint(s.x, g), Vec3(0.5 * s.x.col(30) + 0.5 * s.x.col(31)));
  // on a node: that node at the grip's position
  g.fraction = 0.0;
  const std::vector<ChainConstraint> on =
      pieceConstraints(m, s, std::span<const Grip>(&g, 1), whole);
  ASSERT_EQ(on.size(), 1u);
  EXPECT_EQ(on[0].position, g.position);
  // which grips hold the rigid needle: its links and the swage node, not the thread beyond
  const int swage = m.swage();
  EXPECT_TRUE(
      gripHoldsNeedle(m, Grip{swage - 1, Vec3::Zero(), false, Eigen::Matrix3d::Identity(), 0.9}));
  EXPECT_TRUE(gripHoldsNeedle(m, Grip{swage, Vec3::Zero()}));
  EXPECT_FALSE(
      gripHoldsNeedle(m, Grip{swage, Vec3::Zero(), false, Eigen::Matrix3d::Identity(), 0.1}));
  EXPECT_FALSE(gripHoldsNeedle(m, Grip{swage + 1, Vec3::Zero()}));
}

TEST(SuturePierces, AnActivePierceNeverSlidesOntoTheRigidNeedle) {
  const SutureModel m = needleAndThread();
  SutureState s = SutureState::laidOut(m);
  const int swage = m.swage();
  // the needle held at node 1; a pierce at the swage, and one made before it, a thread link
  // further on, whose point lies 1 mm away: the side between them is taut and asks for thread
  const Grip grip{1, s.x.col(1)};
  s.pierces.push_back(pierceThrough(swage + 1, Vec3(s.x.col(swage + 1)) + Vec3(0, 0, 1)));
  s.pierces.push_back(pierceThrough(swage, s.x.col(swage)));
  std::vector<SutureEvent> events;
  slideAtDefaultTolerance(m, s, std::span<const Grip>(&grip, 1), events);
  EXPECT_TRUE(events.empty());
  ASSERT_EQ(s.pierces.size(), 2u);
  // the thread comes from the tail side; the needle cannot give any
  EXPECT_EQ(s.pierces[1].node, swage);
  EXPECT_GT(s.pierces[0].node, swage + 1);
}

TEST(SuturePierces, AnActivePierceSlidesOnAlongTheThreadAsTheNeedleTurnsAway) {
  const SutureModel m = needleAndThread();
  SutureState s = SutureState::laidOut(m);
  const int swage = m.swage();
  s.pierces.push_back(pierceThrough(swage, s.x.col(swage)));
  // the needle, held at node 1, turns on along its own circle (tip first) until the swage is
  // 0.35 mm past the pierce: the thread between them needs 4 links of 0.1 mm
  const double turn = 2.0 * std::asin(0.35 / 2.0);
  const Vec3 centre(0, 1, 0);
  const Eigen::Matrix3d r = Eigen::AngleAxisd(-turn, Vec3::UnitZ()).toRotationMatrix();
  for (int i = 0; i < m.nodeCount(); ++i) s.x.col(i) = centre + r * (s.x.col(i) - centre);
  ASSERT_NEAR((s.x.col(swage) - s.pierces[0].point).norm(), 0.35, 1e-12);
  const Grip grip{1, s.x.col(1)};
  std::vector<SutureEvent> events;
  EXPECT_EQ(slideAtDefaultTolerance(m, s, std::span<const Grip>(&grip, 1), events), 4);
  ASSERT_EQ(s.pierces.size(), 1u);
  EXPECT_EQ(s.pierces[0].node, swage + 4);
}

TEST(SuturePierces, APassivePierceIsReleasedOnceTheNeedleHasLeftIt) {
  const SutureModel m = needleAndThread();
  const double reach = m.def().pierceReleaseDistance;
  const SutureState laid = SutureState::laidOut(m);
  // halfway between needle nodes 3 and 4, off the needle's plane: the distance that counts is
  // to the needle, not to its nearest node (half a link, 0.15 mm, away)
  const Vec3 between = 0.5 * (laid.x.col(3) + laid.x.col(4));
  const Vec3 tip = laid.x.col(0);
  const Vec3 outOfTip = (laid.x.col(0) - laid.x.col(1)).normalized();
  struct Case {
    Vec3 point;
    bool released;
  };
  const Case cases[] = {{between + 0.9 * reach * Vec3::UnitZ(), false},
                        {between + 1.1 * reach * Vec3::UnitZ(), true},
                        {tip + 0.9 * reach * outOfTip, false},
                        // the needle pulled back out through the hole
                        {tip + 1.1 * reach * outOfTip, true}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.released);
    SutureState s = laid;
    s.pierces.push_back(pierceThrough(3, c.point));
    std::vector<SutureEvent> events;
    slideAtDefaultTolerance(m, s, {}, events);
    if (c.released) {
      EXPECT_TRUE(s.pierces.empty());
      ASSERT_EQ(events.size(), 1u);
      EXPECT_EQ(events[0].kind, SutureEventKind::Released);
      EXPECT_EQ(events[0].pierce, 0);
    } else {
      EXPECT_TRUE(events.empty());
      ASSERT_EQ(s.pierces.size(), 1u);
      EXPECT_LT(s.pierces[0].node, m.swage());
    }
  }
}

TEST(SuturePierces, ReleasingOnePierceKeepsTheOthersAndReportsItsIndex) {
  const SutureModel m = needleAndThread();
  SutureState s = SutureState::laidOut(m);
  // three pierces on the needle, the middle one left 0.2 mm beside it
  s.pierces.push_back(pierceThrough(6, s.x.col(6)));
  s.pierces.push_back(pierceThrough(4, Vec3(s.x.col(4)) + Vec3(0, 0, 0.2)));
  s.pierces.push_back(pierceThrough(2, s.x.col(2)));
  std::vector<SutureEvent> events;
  slideAtDefaultTolerance(m, s, {}, events);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, SutureEventKind::Released);
  EXPECT_EQ(events[0].pierce, 1);
  ASSERT_EQ(s.pierces.size(), 2u);
  EXPECT_EQ(s.pierces[0].node, 6);
  EXPECT_EQ(s.pierces[1].node, 2);
}

TEST(SuturePierces, TwoPassivePiercesKeepTheirOrderWhereTheNeedleWouldSwapThem) {
  const SutureModel m = needleAndThread();
  SutureState s = SutureState::laidOut(m);
  // the needle went through the first pierce before the second, so the first lies farther
  // along it; the tissue has moved the second's point next to node 6, past the first's node 5
  s.pierces.push_back(pierceThrough(5, s.x.col(5)));
  s.pierces.push_back(pierceThrough(3, s.x.col(6)));
  std::vector<SutureEvent> events;
  slideAtDefaultTolerance(m, s, {}, events);
  ASSERT_EQ(s.pierces.size(), 2u);
  EXPECT_EQ(s.pierces[0].node, 5);
  EXPECT_LE(s.pierces[1].node, s.pierces[0].node);
}

TEST(SuturePierces, APassivePierceWaitsOnTheNeedleWhileThePierceAheadHoldsTheSwage) {
  const SutureModel m = needleAndThread();
  const int swage = m.swage();
  for (const bool needleHeld : {false, true}) {
    SCOPED_TRACE(needleHeld);
    SutureState s = SutureState::laidOut(m);
    const Grip grip{1, s.x.col(1)};
    const std::span<const Grip> grips =
        needleHeld ? std::span<const Grip>(&grip, 1) : std::span<const Grip>();
    // the first pierce has just reached the swage; the second, right behind it, is nearest
    // the swage too: both cannot hold node 8, and the first may not fall back onto the needle
    s.pierces.push_back(pierceThrough(swage, s.x.col(swage)));
    s.pierces.push_back(pierceThrough(swage - 1, Vec3(s.x.col(swage)) + Vec3(0, 0, 0.01)));
    std::vector<SutureEvent> events;
    slideAtDefaultTolerance(m, s, grips, events);
    EXPECT_TRUE(events.empty());
    ASSERT_EQ(s.pierces.size(), 2u);
    EXPECT_GE(s.pierces[0].node, swage);
    EXPECT_LT(s.pierces[1].node, s.pierces[0].node);
  }
}

TEST(SuturePierces, ActivePiercesPulledTowardsEachOtherDoNotCross) {
  const SutureModel m = needleAndThread();
  SutureState s = SutureState::laidOut(m);
  const int swage = m.swage();
  // two thread pierces whose points swapped places: each side between them is taut
  const Vec3 a = s.x.col(swage + 20);
  const Vec3 b = s.x.col(swage + 10);
  s.pierces.push_back(pierceThrough(swage + 20, b));
  s.pierces.push_back(pierceThrough(swage + 10, a));
  const Grip grips[2] = {{swage, s.x.col(swage)}, {m.nodeCount() - 1, s.x.col(m.nodeCount() - 1)}};
  std::vector<SutureEvent> events;
  slideAtDefaultTolerance(m, s, grips, events);
  ASSERT_EQ(s.pierces.size(), 2u);
  EXPECT_GT(s.pierces[0].node, s.pierces[1].node);
  EXPECT_GT(s.pierces[1].node, swage);
}

TEST(SuturePierces, AStitchsFourHolesAreDrawnThroughTogetherWhenOneEndIsPulled) {
  const SutureModel m = needleAndThread();
  SutureState s = SutureState::laidOut(m);
  const int swage = m.swage();
  // a stitch on a straight, taut thread: a wall's two holes on neighbouring nodes (a wall
  // thinner than a link), the lumen across 5 links, the other wall; the tail free beyond
  const int holes[4] = {swage + 27, swage + 26, swage + 21, swage + 20};
  for (int node : holes) s.pierces.push_back(pierceThrough(node, s.x.col(node)));
  // the thread taken 10 links before the stitch and drawn 0.35 mm back along itself: it needs
  // 14 links to the stitch, which the tail gives through all four holes
  const Vec3 along = (s.x.col(swage + 20) - s.x.col(swage + 10)).normalized();
  const Grip grip{swage + 10, s.x.col(swage + 10) - 0.35 * along};
  std::vector<SutureEvent> events;
  EXPECT_EQ(slideAtDefaultTolerance(m, s, std::span<const Grip>(&grip, 1), events), 4);
  EXPECT_TRUE(events.empty());
  ASSERT_EQ(s.pierces.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) EXPECT_EQ(s.pierces[k].node, holes[k] + 4) << k;
}

// A hole beside turns wound on a forceps' jaws (the instrument tie): the long end runs from the
// hole 5 links to the turns, round them, and on to the hand. Its straight span to the hand is
// far short of its arc, so measured to the hand the hole's side reads slack, and a tail pulled
// taut drew it through the hole link by link. Measured to the turns, the side is taut as well:
// the tail only stretches (the turns, not the hole, give: they slide along the jaws).
TEST(SuturePierces, AHoleBesideTurnsWoundOnTheJawsDrawsNoThreadThroughThem) {
  SutureDef d;
  d.links = 40;
  d.needleLinks = 0;
  d.length = 4.0;
  const SutureModel m(d);
  const auto laid = [&] {
    SutureState s = SutureState::laidOut(m);
    // nodes 0..10 coiled tight near the origin (the hand at node 0, the turns 1..10), the side
    // 10..15 straight and taut along +x to the hole at node 15, the tail 15..20 to a grip at
    // node 20 pulled 10 % past its length
    for (int i = 0; i <= 10; ++i)
      s.x.col(i) = Vec3(0.05 * std::cos(0.6 * i), 0.05 * std::sin(0.6 * i), 0.005 * i);
    for (int i = 11; i <= 15; ++i) s.x.col(i) = s.x.col(10) + Vec3(0.1 * (i - 10), 0.0, 0.0);
    for (int i = 16; i <= 40; ++i) s.x.col(i) = s.x.col(15) + Vec3(0.11 * (i - 15), 0.0, 0.0);
    s.xPrev = s.x;
    s.pierces.push_back(pierceThrough(15, s.x.col(15)));
    return s;
  };
  std::array<Grip, 2> grips;
  grips[1].node = 20;
  std::vector<SutureEvent> events;
  const std::array<std::array<int, 2>, 1> wound{{{1, 10}}};

  SutureState measuredToTheHand = laid();
  grips[0].position = measuredToTheHand.x.col(0);
  grips[1].position = measuredToTheHand.x.col(20);
  EXPECT_GT(slideAtDefaultTolerance(m, measuredToTheHand, grips, events), 0);
  EXPECT_LT(measuredToTheHand.pierces[0].node, 15);

  SutureState measuredToTheTurns = laid();
  EXPECT_EQ(
      slidePierces(m, measuredToTheTurns, grips, SutureStepParams{}.slideTolerance, events, wound),
      0);
  EXPECT_EQ(measuredToTheTurns.pierces[0].node, 15);
}

}  // namespace
}  // namespace microsim::sim::suture
