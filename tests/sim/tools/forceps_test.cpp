#include "microsim/sim/tools/forceps.h"

#include "microsim/sim/scene/scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <variant>

namespace microsim::sim {
namespace {

const std::string kForcepsMeshes = std::string(MICROSIM_SOURCE_DIR) + "/resources/meshes";

ForcepsDef jawDef() {
  ForcepsDef def;
  def.jawVertices.resize(3, 3);
  def.jawVertices << 0, 3, 3, 0, 0, 0.1, 0, 0.1, 0;
  def.jawTriangles = {{0, 1, 2}};
  def.openingDeg = 20.0;
  return def;
}

TEST(Forceps, JawTipsMeetWhenClosedAndOpenBySymmetricAngles) {
  const ForcepsDef def = jawDef();
  EXPECT_DOUBLE_EQ(tools::jawLength(def), 3.0);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Vec3(1, 2, 3);
  const auto closed = tools::jawTips(def, pose, 1.0);
  EXPECT_LT((closed[0] - Vec3(1, 2, 3)).norm(), 1e-15);
  EXPECT_LT((closed[1] - Vec3(1, 2, 3)).norm(), 1e-15);
  const auto open = tools::jawTips(def, pose, 0.0);
  const double t = 20.0 * std::numbers::pi / 180.0;
  EXPECT_LT((open[0] - Vec3(1 + 3 - 3 * std::cos(t), 2 + 3 * std::sin(t), 3)).norm(), 1e-12);
  EXPECT_LT((open[1] - Vec3(1 + 3 - 3 * std::cos(t), 2 - 3 * std::sin(t), 3)).norm(), 1e-12);
  // the lower jaw is the mirror image, wound the other way
  const Points v = tools::jawVertices(def, pose, 0.0);
  EXPECT_NEAR(v(1, 5) - 2.0, -(v(1, 2) - 2.0), 1e-12);
  EXPECT_EQ(tools::jawTriangles(def).back(), (std::array<int, 3>{3, 5, 4}));
}

TEST(Forceps, PointsNearASegmentSkipTheMarkedOnes) {
  Points x(3, 4);
  x << 0, 1, 2, 1, 0.05, 0, 0, 0.2, 0, 0, 0, 0;
  EXPECT_EQ(tools::pointsNearSegment(x, Vec3(0, 0, 0), Vec3(2, 0, 0), 0.1), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(tools::pointsNearSegment(x, Vec3(0, 0, 0), Vec3(2, 0, 0), 0.1, {0, 1, 0, 0}),
            (std::vector<int>{0, 2}));
}

SceneDef latticeWithForceps() {
  const std::string text = R"({"objects": [{"type": "lattice", "size": [4, 4, 4], "stiffness": 10}],
    "solver": {"name": "newton", "iterations": 50, "tolerance": 1e-10},
    "tools": {"forceps": [{"hand": "right", "mesh": "forceps_jaw.obj"}]}})";
  SceneDefLoad load = parseSceneDef(text, "grab.json", kForcepsMeshes);
  EXPECT_TRUE(std::holds_alternative<SceneDef>(load));
  return std::get<SceneDef>(std::move(load));
}

InputFrame forcepsAt(const Vec3& tip, double closure, int k) {
  InputFrame f;
  f.time = 0.01 * k;
  f.hand(Hand::Left).instrument = Instrument::None;
  HandInput& h = f.hand(Hand::Right);
  h.instrument = Instrument::Forceps;
  h.tracked = true;
  h.position = tip;
  h.closure = closure;
  return f;
}

TEST(Forceps, GrabMovesTheNodesBetweenTheTipsAndReleaseFreesThem) {
  Scene scene(latticeWithForceps());
  const Points& rest = scene.tissue().restPositions();
  int node = -1;
  int below = -1;
  for (int i = 0; i < scene.tissue().nodeCount(); ++i) {
    if (rest.col(i) == Vec3(1, 1, 3)) node = i;
    if (rest.col(i) == Vec3(1, 1, 2)) below = i;
  }
  ASSERT_GE(node, 0);
  int k = 0;
  scene.step(forcepsAt(Vec3(1, 1, 3), 0.0, k++));
  scene.step(forcepsAt(Vec3(1, 1, 3), 1.0, k++));
  ASSERT_EQ(scene.forceps(Hand::Right)->heldNodes(), std::vector<int>{node});
  ASSERT_FALSE(scene.events().empty());
  EXPECT_EQ(scene.events().back().kind, SceneEventKind::GrabTissue);
  EXPECT_EQ(scene.events().back().count, 1);

  // lifted 0.5 mm: the held node follows exactly (from where it was taken: the open jaws
  // set down on it had pressed it in a little), the one under it is pulled along
  const Vec3 taken = scene.tissueState().x.col(node);
  EXPECT_LT((taken - Vec3(1, 1, 3)).norm(), 0.1);
  for (int s = 1; s <= 10; ++s) scene.step(forcepsAt(Vec3(1, 1, 3 + 0.05 * s), 1.0, k++));
  EXPECT_LT((scene.tissueState().x.col(node) - (taken + Vec3(0, 0, 0.5))).norm(), 1e-12);
  EXPECT_GT(scene.tissueState().x(2, below) - 2.0, 0.05);
  ASSERT_EQ(scene.controls().size(), 1);

  // opened: released, no control left, and the box springs back to rest
  scene.step(forcepsAt(Vec3(1, 1, 3.5), 0.0, k++));
  EXPECT_EQ(scene.events().back().kind, SceneEventKind::ReleaseTissue);
  EXPECT_TRUE(scene.forceps(Hand::Right)->heldNodes().empty());
  EXPECT_EQ(scene.controls().size(), 0);
  for (int s = 0; s < 5; ++s) scene.step(forcepsAt(Vec3(1, 1, 3.5), 0.0, k++));
  EXPECT_LT((scene.tissueState().x.col(node) - Vec3(1, 1, 3)).norm(), 1e-6);
}

TEST(Forceps, AnOpenForcepsOrOneClosedOnNothingHoldsNothing) {
  Scene scene(latticeWithForceps());
  scene.step(forcepsAt(Vec3(10, 10, 10), 0.0, 0));
  scene.step(forcepsAt(Vec3(10, 10, 10), 1.0, 1));
  EXPECT_TRUE(scene.forceps(Hand::Right)->heldNodes().empty());
  scene.step(forcepsAt(Vec3(1, 1, 3), 1.0, 2));  // already closed when it arrives
  EXPECT_TRUE(scene.forceps(Hand::Right)->heldNodes().empty());
  EXPECT_TRUE(scene.events().empty());
}

TEST(Forceps, RejectedInputIsReportedAndTheLastGoodFrameIsUsed) {
  Scene scene(latticeWithForceps());
  scene.step(forcepsAt(Vec3(1, 1, 3), 0.0, 0));
  scene.step(forcepsAt(Vec3(1, 1, 3), 1.0, 1));
  InputFrame bad = forcepsAt(Vec3(1, 1, std::nan("")), 1.0, 2);
  const StepReport r = scene.step(bad);
  EXPECT_TRUE(r.inputRejected);
  EXPECT_EQ(scene.events().back().kind, SceneEventKind::InputRejected);
  EXPECT_EQ(scene.events().back().rejection, InputRejection::NonFinite);
  EXPECT_EQ(scene.forceps(Hand::Right)->heldNodes().size(), 1u);
  EXPECT_TRUE(scene.tissueState().x.allFinite());
  InputFrame back = forcepsAt(Vec3(1, 1, 3), 1.0, 0);  // time going backwards
  scene.step(back);
  EXPECT_EQ(scene.events().back().rejection, InputRejection::TimeBackwards);
}

}  // namespace
}  // namespace microsim::sim
