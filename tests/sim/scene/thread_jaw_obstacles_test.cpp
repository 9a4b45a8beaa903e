// The jaws as the thread meets them (sim/src/scene/thread_jaw_obstacles.h), one forceps at a
// time: the shipped forceps (jaws 3 mm long, 20° open) upright at the origin, its jaws rising
// along +z and opening along ±y, and a few chain nodes placed where each rule looks.
#include "scene/thread_jaw_obstacles.h"

#include "microsim/sim/collide/segment_segment.h"
#include "microsim/sim/scene/scene.h"

#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace microsim::sim {
namespace {

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
  f.update(pose, from, released);
  f.update(pose, closure, released);
  return f;
}

Points chainOf(const std::vector<Vec3>& nodes) {
  Points x(3, static_cast<Eigen::Index>(nodes.size()));
  for (std::size_t i = 0; i < nodes.size(); ++i) x.col(static_cast<Eigen::Index>(i)) = nodes[i];
  return x;
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
    std::vector<suture::Capsule> out;
    appendThreadJawObstacles(uprightForceps(*def, closure, closure), x, -1, kObstacleThreadRadius, out);
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
  std::vector<suture::Capsule> full;
  appendThreadJawObstacles(uprightForceps(*def, 1.0, 1.0), x, -1, kObstacleThreadRadius, full);
  ASSERT_EQ(full.size(), 4U);
  std::vector<suture::Capsule> out;
  appendThreadJawObstacles(uprightForceps(*def, 0.3, 0.5), x, -1, kObstacleThreadRadius, out);
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
  std::vector<suture::Capsule> out;
  appendThreadJawObstacles(uprightForceps(*def, 0.3, 0.3), x, 2, kObstacleThreadRadius, out);
  EXPECT_TRUE(out.empty()) << "a needle lying free: the opened jaws reach round it";
  appendThreadJawObstacles(uprightForceps(*def, 0.3, 0.3), x, -1, kObstacleThreadRadius, out);
  EXPECT_EQ(out.size(), 4U) << "a needle hanging from held thread (the scene passes -1)";
  out.clear();
  appendThreadJawObstacles(uprightForceps(*def, 1.0, 1.0), x, 2, kObstacleThreadRadius, out);
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
  std::vector<suture::Capsule> out;
  appendThreadJawObstacles(holding, x, -1, kObstacleThreadRadius, out);
  ASSERT_EQ(out.size(), 4U);
  for (const suture::Capsule& c : out) {
    // from the node at the tip (z = 0; the one 0.1 mm below it is outside) to the last
    EXPECT_EQ(c.freeFirst, 10);
    EXPECT_EQ(c.freeLast, 39);
  }
}

}  // namespace
}  // namespace microsim::sim
