// The jaws as the thread meets them (sim/src/scene/thread_jaw_obstacles.h), one forceps at a
// time: the shipped forceps (jaws 3 mm long, 20° open) upright at the origin, its jaws rising
// along +z and opening along ±y, and a few chain nodes placed where each rule looks.
#include "scene/thread_jaw_obstacles.h"

#include "microsim/sim/collide/segment_segment.h"
#include "microsim/sim/scene/scene.h"

#include "support/chain_points.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace microsim::sim {
namespace {

using microsim::testing::chainOf;

const std::string kObstacleSceneRoot = MICROSIM_SOURCE_DIR;
constexpr double kObstacleThreadRadius = 0.01;  // mm

std::optional<ForcepsDef> shippedForceps() {
  SceneDefLoad load = loadSceneDef(kObstacleSceneRoot + "/resources/scenes/anastomosis.json");
  if (!std::holds_alternative<SceneDef>(load)) return std::nullopt;
  return std::get<SceneDef>(load).forceps[0];
}

/// The forceps upright at the origin, moved from closure `from` to `closure`.
tools::Forceps uprightForceps(const ForcepsDef& def, double from, double closure) {
  Eigen::Matrix3d frame;
  frame.col(0) = Vec3::UnitZ();  // tip → hinge
  frame.col(1) = Vec3::UnitY();  // the jaws open along ±y
  frame.col(2) = Vec3::UnitZ().cross(Vec3::UnitY());
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = frame;
  tools::Forceps f(def);
  bool released = false;
  f.update(pose, from, 1.0, released);  // a second: time enough to open
  f.update(pose, closure, 1.0, released);
  return f;
}

/// The capsules the jaws of `forceps` are to the chain x (a free needle on nodes 0..swage).
std::vector<suture::Capsule> capsulesOf(const tools::Forceps& forceps, const Points& x, int swage) {
  const std::vector<std::uint8_t> alive(static_cast<std::size_t>(x.cols()) - 1, 1);
  suture::SutureWorld world;
  appendThreadJawObstacles(forceps, {x, alive, swage, 0, kObstacleThreadRadius}, world);
  return world.capsules;
}

/// mm: how far node p keeps outside the capsules (negative: inside one).
double capsuleClearance(const std::vector<suture::Capsule>& capsules, const Vec3& p) {
  double clear = 1e9;
  for (const suture::Capsule& c : capsules) {
    const double t = collide::closestParameterOnSegment(p, c.a, c.b);
    clear = std::min(clear, (p - ((1.0 - t) * c.a + t * c.b)).norm() - c.radius);
  }
  return clear;
}

TEST(ThreadJawObstacles, ClosedOrOpenedJawsWithNothingBetweenThemAreFullCapsules) {
  const std::optional<ForcepsDef> def = shippedForceps();
  ASSERT_TRUE(def);
  // a thread 1 mm beside the jaws, along x
  const Points x = chainOf({Vec3(-0.5, 1.0, 1.0), Vec3(0.0, 1.0, 1.0), Vec3(0.5, 1.0, 1.0)});
  for (const double closure : {1.0, 0.3}) {
    const std::vector<suture::Capsule> out =
        capsulesOf(uprightForceps(*def, closure, closure), x, -1);
    ASSERT_EQ(out.size(), 4U) << closure;
    // the heel halves are as thick as the jaw mesh's heel (0.15 × 0.12 mm: 0.19 mm round)
    EXPECT_NEAR(out[1].radius, 0.192, 0.001);
    EXPECT_NEAR(out[3].radius, 0.192, 0.001);
  }
}

TEST(ThreadJawObstacles, ThreadBetweenOpenedJawsIsLeftClearForThemToClose) {
  const std::optional<ForcepsDef> def = shippedForceps();
  ASSERT_TRUE(def);
  // jaws closing from 0.3 to 0.5 on a thread across them 2.5 mm up, on their middle line,
  // where their axes were 0.25 mm apart: capsules 0.19 mm round the axes would hold it
  const Points x = chainOf({Vec3(-0.05, 0.0, 2.5), Vec3(0.0, 0.0, 2.5), Vec3(0.05, 0.0, 2.5)});
  std::vector<suture::Capsule> full = capsulesOf(uprightForceps(*def, 1.0, 1.0), x, -1);
  ASSERT_EQ(full.size(), 4U);
  std::vector<suture::Capsule> out = capsulesOf(uprightForceps(*def, 0.3, 0.5), x, -1);
  ASSERT_EQ(out.size(), 4U);
  // thinned where the thread lies, a thread's radius clear of it, and only there
  EXPECT_LT(out[1].radius, full[1].radius - 0.05);
  for (Eigen::Index i = 0; i < x.cols(); ++i) EXPECT_GE(capsuleClearance(out, x.col(i)), kObstacleThreadRadius - 1e-12) << i;
  EXPECT_DOUBLE_EQ(out[0].radius, full[0].radius);
}

TEST(ThreadJawObstacles, OpenedJawsRoundAFreeNeedleAreLeftOut) {
  const std::optional<ForcepsDef> def = shippedForceps();
  ASSERT_TRUE(def);
  // a needle (nodes 0..2) 0.3 mm beside the opened jaws' tips, then thread
  const Points x = chainOf({Vec3(0.3, 0.6, 0.1), Vec3(0.45, 0.6, 0.1), Vec3(0.6, 0.6, 0.1), Vec3(0.75, 0.6, 0.1)});
  std::vector<suture::Capsule> out = capsulesOf(uprightForceps(*def, 0.3, 0.3), x, 2);
  EXPECT_TRUE(out.empty()) << "a needle lying free: the opened jaws reach round it";
  out = capsulesOf(uprightForceps(*def, 0.3, 0.3), x, -1);
  EXPECT_EQ(out.size(), 4U) << "a needle hanging from held thread (the scene passes -1)";
  out = capsulesOf(uprightForceps(*def, 1.0, 1.0), x, 2);
  EXPECT_EQ(out.size(), 4U) << "closed jaws are solid wherever the needle is";
}

TEST(ThreadJawObstacles, JawsHoldingTheThreadLetOnlyTheHeldRunThrough) {
  const std::optional<ForcepsDef> def = shippedForceps();
  ASSERT_TRUE(def);
  // a thread up the jaws' axis from their tip, held at its fourth node: the held thread lies
  // inside both jaws, and the nodes inside them on either side pass; the rest meets them
  Points x(3, 40);
  for (int i = 0; i < 40; ++i) x.col(i) = Vec3(0.0, 0.0, -1.0 + 0.1 * i);  // the jaws span z 0..3
  const suture::SutureDef sutureDef = [] {
    suture::SutureDef d;
    d.needleLinks = 0;
    d.links = 39;
    d.length = 3.9;
    return d;
  }();
  const suture::SutureModel model(sutureDef);
  tools::Forceps holding = uprightForceps(*def, 0.0, 1.0);
  holding.holdSuture({12, 0.0, 0.0}, model, x);
  ASSERT_TRUE(holding.holdsSuture());
  std::vector<suture::Capsule> out = capsulesOf(holding, x, -1);
  ASSERT_EQ(out.size(), 4U);
  for (const suture::Capsule& c : out) {
    // from the node at the tip (z = 0; the one 0.1 mm below it is outside) to the last
    EXPECT_EQ(c.freeFirst, 10);
    EXPECT_EQ(c.freeLast, 39);
  }
}

// Turns wound on the jaws (the header's second essay). The forceps upright and closed: its jaws
// rise along +z from the tip at the origin, 0.12 mm round over their lower half.

/// A thread coming in from 1 mm off, then `turns` turns round the z axis `radius` mm out,
/// climbing from z = `from` by 0.3 mm a turn, 9 nodes a turn, then out to 1 mm off again.
Points woundThread(double turns, double radius, double from) {
  std::vector<Vec3> nodes{Vec3(-1.0, 0.0, from), Vec3(-0.5, 0.0, from)};
  const int steps = static_cast<int>(std::lround(9 * turns));
  for (int k = 0; k <= steps; ++k) {
    const double phi = 2.0 * std::numbers::pi * k / 9.0;
    nodes.emplace_back(-radius * std::cos(phi), -radius * std::sin(phi), from + 0.3 * k / 9.0);
  }
  const Vec3 end = nodes.back();
  nodes.emplace_back(end + 0.5 * (end - Vec3(0.0, 0.0, end.z())).normalized());
  nodes.emplace_back(end + 1.0 * (end - Vec3(0.0, 0.0, end.z())).normalized());
  return chainOf(nodes);
}

std::vector<std::array<int, 2>> woundOn(const tools::Forceps& forceps, const Points& x) {
  const std::vector<std::uint8_t> alive(static_cast<std::size_t>(x.cols()) - 1, 1);
  return threadWoundOnJaws(forceps, {x, alive, -1, 0, kObstacleThreadRadius});
}

TEST(ThreadJawObstacles, TwoTurnsRoundTheJawsAreOneWoundRunThatASleeveKeeps) {
  const std::optional<ForcepsDef> def = shippedForceps();
  ASSERT_TRUE(def);
  const tools::Forceps closed = uprightForceps(*def, 1.0, 1.0);
  const Points x = woundThread(2.0, 0.14, 0.6);  // nodes 2..20 round the jaws
  EXPECT_EQ(woundOn(closed, x), (std::vector<std::array<int, 2>>{{2, 20}}));
  const std::vector<std::uint8_t> alive(static_cast<std::size_t>(x.cols()) - 1, 1);
  suture::SutureWorld world;
  appendThreadJawObstacles(closed, {x, alive, -1, 0, kObstacleThreadRadius}, world);
  ASSERT_EQ(world.sleeves.size(), 1U);
  EXPECT_EQ(world.sleeves[0].first, 2);
  EXPECT_EQ(world.sleeves[0].last, 20);
  EXPECT_EQ(world.capsules.size(), 4U);
  // turns 0.6 mm round the jaws' axis are not on them
  EXPECT_TRUE(woundOn(closed, woundThread(2.0, 0.6, 0.6)).empty());
}

TEST(ThreadJawObstacles, LessThanThreeQuartersOfATurnOrAStrandAlongTheJawsIsNotWound) {
  const std::optional<ForcepsDef> def = shippedForceps();
  ASSERT_TRUE(def);
  const tools::Forceps closed = uprightForceps(*def, 1.0, 1.0);
  EXPECT_TRUE(woundOn(closed, woundThread(0.5, 0.14, 0.6)).empty());
  EXPECT_EQ(woundOn(closed, woundThread(1.0, 0.14, 0.6)).size(), 1U);
  std::vector<Vec3> along(20);
  for (std::size_t k = 0; k < along.size(); ++k)
    along[k] = Vec3(0.14, 0.0, 0.1 + 0.1 * static_cast<double>(k));
  EXPECT_TRUE(woundOn(closed, chainOf(along)).empty());
}

TEST(ThreadJawObstacles, TurnsSlidOffPastTheTipsAreNotOnTheJaws) {
  const std::optional<ForcepsDef> def = shippedForceps();
  ASSERT_TRUE(def);
  const tools::Forceps closed = uprightForceps(*def, 1.0, 1.0);
  // round the jaws' line below their tips: the turns have come off
  EXPECT_TRUE(woundOn(closed, woundThread(2.0, 0.14, -1.0)).empty());
  // half of them off: the turn still round the jaws is wound, the rest is not
  const std::vector<std::array<int, 2>> half = woundOn(closed, woundThread(2.0, 0.14, -0.3));
  ASSERT_EQ(half.size(), 1U);
  EXPECT_GE(half[0][0], 10);
  EXPECT_EQ(half[0][1], 20);
}

}  // namespace
}  // namespace microsim::sim
