#include "microsim/sim/suture/chain_projection.h"
#include "microsim/sim/suture/follow_the_leader.h"
#include "microsim/sim/suture/suture_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace microsim::sim::suture {
namespace {

SutureDef threadOnlyDef(int links, double length) {
  SutureDef d;
  d.links = links;
  d.needleLinks = 0;
  d.length = length;
  return d;
}

// a wavy chain with exact rest lengths, 3 by (N + 1)
Points wavy(const SutureModel& model) {
  Points x(3, model.nodeCount());
  x.col(0).setZero();
  for (int i = 0; i < model.linkCount(); ++i) {
    const double a = 0.3 * std::sin(0.2 * i);
    const double b = 0.2 * std::cos(0.13 * i);
    x.col(i + 1) = x.col(i) + model.rest(i) * Vec3(std::cos(a) * std::cos(b), std::sin(a) * std::cos(b), std::sin(b));
  }
  return x;
}

double worstLengthError(const SutureModel& model, const Points& x) {
  double worst = 0.0;
  for (int i = 0; i < model.linkCount(); ++i)
    worst = std::max(worst, std::abs((x.col(i + 1) - x.col(i)).norm() - model.rest(i)) / model.rest(i));
  return worst;
}

TEST(SutureModel, CurvedNeedleIsAThreeEighthsArcAndTheThreadHasItsLength) {
  SutureDef d;  // 200 links, 8 needle links, curved R = 1
  const SutureModel m(d);
  EXPECT_EQ(m.nodeCount(), 201);
  EXPECT_NEAR(m.arc(m.swage(), m.nodeCount() - 1), d.length, 1e-12);
  // every needle node on the circle of radius R centred at (0, R, 0)
  for (int k = 0; k <= m.needleLinks(); ++k)
    EXPECT_NEAR((m.needleShape().col(k) - Vec3(0, d.needleRadius, 0)).norm(), d.needleRadius, 1e-12);
  // the tip-to-swage angle is 3π/4
  const Vec3 tip = m.needleShape().col(0) - Vec3(0, 1, 0);
  const Vec3 swage = m.needleShape().col(m.needleLinks()) - Vec3(0, 1, 0);
  EXPECT_NEAR(std::acos(tip.normalized().dot(swage.normalized())), 0.75 * std::numbers::pi, 1e-12);
  // laid out at rest: every link at its rest length
  const SutureState s = SutureState::laidOut(m);
  EXPECT_LT(worstLengthError(m, s.x), 1e-12);
}

TEST(SutureModel, ChainPiecesSplitAtBrokenLinks) {
  std::vector<std::uint8_t> alive(10, 1);
  alive[3] = 0;
  alive[7] = 0;
  const std::vector<Piece> p = chainPieces(alive);
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[0].first, 0);
  EXPECT_EQ(p[0].last, 3);
  EXPECT_EQ(p[1].first, 4);
  EXPECT_EQ(p[1].last, 7);
  EXPECT_EQ(p[2].first, 8);
  EXPECT_EQ(p[2].last, 10);
}

TEST(FollowTheLeader, EveryLinkKeepsItsLengthAfterAnyOneLeaderMove) {
  const SutureModel m(threadOnlyDef(200, 20.0));
  const std::vector<std::uint8_t> alive(200, 1);
  const int nodes[] = {0, 1, 57, 100, 199, 200};
  const Vec3 moves[] = {Vec3(0.05, 0, 0), Vec3(3, -2, 1), Vec3(0, 0, 25), Vec3(-40, 10, 7)};
  for (int node : nodes)
    for (const Vec3& move : moves) {
      Points x = wavy(m);
      const Leader l{node, Vec3(x.col(node)) + move};
      followTheLeader(m, x, alive, std::span<const Leader>(&l, 1));
      EXPECT_LT(worstLengthError(m, x), 1e-9) << "node " << node;
      EXPECT_EQ(x.col(node), l.position);
    }
}

TEST(FollowTheLeader, TheLeadersNeighbourGoesOnTheLineToItsOldPosition) {
  const SutureModel m(threadOnlyDef(4, 4.0));  // links of 1 mm, paper Fig. 6
  Points x(3, 5);
  x << 0, 1, 2, 3, 4,
       0, 0, 0, 0, 0,
       0, 0, 0, 0, 0;
  const Leader l{2, Vec3(2, 1, 0)};
  followTheLeader(m, x, std::vector<std::uint8_t>(4, 1), std::span<const Leader>(&l, 1));
  // node 3 on the line from (2, 1, 0) to its old (3, 0, 0), at distance 1
  const Vec3 expected3 = Vec3(2, 1, 0) + (Vec3(3, 0, 0) - Vec3(2, 1, 0)).normalized();
  EXPECT_LT((x.col(3) - expected3).norm(), 1e-15);
  const Vec3 expected4 = expected3 + (Vec3(4, 0, 0) - expected3).normalized();
  EXPECT_LT((x.col(4) - expected4).norm(), 1e-15);
  const Vec3 expected1 = Vec3(2, 1, 0) + (Vec3(1, 0, 0) - Vec3(2, 1, 0)).normalized();
  EXPECT_LT((x.col(1) - expected1).norm(), 1e-15);
}

TEST(FollowTheLeader, BetweenTwoLeadersThePassesAreAveraged) {
  const SutureModel m(threadOnlyDef(60, 6.0));
  const std::vector<std::uint8_t> alive(60, 1);
  const Points old = wavy(m);
  Points x = old;
  const std::vector<Leader> leaders = {{10, Vec3(old.col(10)) + Vec3(0.3, 0.2, 0)},
                                       {40, Vec3(old.col(40)) + Vec3(-0.1, 0.4, 0.2)}};
  followTheLeader(m, x, alive, leaders);

  // the two passes by hand
  Points forward = old;
  Points backward = old;
  forward.col(10) = leaders[0].position;
  backward.col(40) = leaders[1].position;
  followChain(forward, m.restLengths(), 10, 40);
  followChain(backward, m.restLengths(), 40, 10);
  for (int k = 11; k < 40; ++k)
    EXPECT_LT((x.col(k) - 0.5 * (forward.col(k) + backward.col(k))).norm(), 1e-15) << k;
  // outside the span lengths are exact; inside the average stretches them (the paper's artefact)
  for (int i = 0; i < 10; ++i)
    EXPECT_NEAR((x.col(i + 1) - x.col(i)).norm(), m.rest(i), 1e-9 * m.rest(i));
  for (int i = 40; i < 60; ++i)
    EXPECT_NEAR((x.col(i + 1) - x.col(i)).norm(), m.rest(i), 1e-9 * m.rest(i));
}

TEST(FollowTheLeader, CoincidentOldAndNewPositionsKeepTheChainFinite) {
  const SutureModel m(threadOnlyDef(5, 5.0));
  Points x = Points::Zero(3, 6);  // every node at one point
  const Leader l{0, Vec3::Zero()};
  followTheLeader(m, x, std::vector<std::uint8_t>(5, 1), std::span<const Leader>(&l, 1));
  EXPECT_TRUE(x.allFinite());
  EXPECT_LT(worstLengthError(m, x), 1e-12);
}

TEST(ChainProjection, RestoresExactLengthsBetweenTwoLeaders) {
  const SutureModel m(threadOnlyDef(100, 10.0));
  const std::vector<std::uint8_t> alive(100, 1);
  Points x = wavy(m);
  const double span = (x.col(80) - x.col(20)).norm();
  ASSERT_LT(span, m.arc(20, 80));
  // move the leaders a little closer, follow-the-leader, then project
  const std::vector<Leader> leaders = {{20, Vec3(x.col(20)) + Vec3(0.2, 0.1, 0)},
                                       {80, Vec3(x.col(80)) + Vec3(-0.3, 0.2, 0.1)}};
  followTheLeader(m, x, alive, leaders);
  EXPECT_GT(worstLengthError(m, x), 1e-4);
  std::vector<double> w(101, 1.0);
  w[20] = w[80] = 0.0;
  ChainProjectionScratch scratch;
  const ChainProjectionResult r = projectChainLengths(x, m.restLengths(), w, alive, 20, 1e-13, scratch);
  EXPECT_LT(r.residual, 1e-12);
  EXPECT_LE(r.iterations, 8);
  EXPECT_LT(worstLengthError(m, x), 1e-9);
  EXPECT_EQ(x.col(20), leaders[0].position);
  EXPECT_EQ(x.col(80), leaders[1].position);
}

TEST(ChainProjection, AnOverLongSpanSpreadsTheStretchWithoutNaN) {
  const SutureModel m(threadOnlyDef(10, 10.0));
  const std::vector<std::uint8_t> alive(10, 1);
  Points x(3, 11);
  for (int i = 0; i <= 10; ++i) x.col(i) = Vec3(i, 0.01 * (i % 2), 0);
  x.col(10) = Vec3(12, 0, 0);  // 20 % past the chain's length
  std::vector<double> w(11, 1.0);
  w[0] = w[10] = 0.0;
  ChainProjectionScratch scratch;
  projectChainLengths(x, m.restLengths(), w, alive, 50, 1e-12, scratch);
  ASSERT_TRUE(x.allFinite());
  for (int i = 0; i < 10; ++i) EXPECT_NEAR((x.col(i + 1) - x.col(i)).norm(), 1.2, 0.2);
}

TEST(ChainProjection, BrokenLinksSeparateThePieces) {
  const SutureModel m(threadOnlyDef(6, 6.0));
  std::vector<std::uint8_t> alive(6, 1);
  alive[2] = 0;
  Points x(3, 7);
  for (int i = 0; i <= 6; ++i) x.col(i) = Vec3(1.1 * i, 0, 0);
  std::vector<double> w(7, 1.0);
  ChainProjectionScratch scratch;
  projectChainLengths(x, m.restLengths(), w, alive, 20, 1e-13, scratch);
  for (int i = 0; i < 6; ++i)
    if (alive[i]) {
      EXPECT_NEAR((x.col(i + 1) - x.col(i)).norm(), 1.0, 1e-9);
    }
  EXPECT_GT((x.col(3) - x.col(2)).norm(), 1.0);  // the broken link is free to gape
}

}  // namespace
}  // namespace microsim::sim::suture
