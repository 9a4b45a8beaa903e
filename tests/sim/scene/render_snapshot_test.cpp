// The snapshot the viewport draws: it mirrors the scene's state after a step (positions,
// unit normals pointing out of the wall, the suture, the forceps' poses, a scalpel or the
// scissors in a hand and what each hand holds, what each forceps' jaws would close on), and
// refilling it follows the scene as it moves.
#include "microsim/sim/scene/render_snapshot.h"

#include "microsim/sim/scene/scene.h"
#include "microsim/sim/scene/stitch_script.h"
#include "microsim/sim/tools/microscissors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <variant>

namespace microsim::sim {
namespace {

const std::string kSnapshotTestRoot = MICROSIM_SOURCE_DIR;

SceneDef renderSnapshotAnastomosis() {
  SceneDefLoad load = loadSceneDef(kSnapshotTestRoot + "/resources/scenes/anastomosis.json");
  EXPECT_TRUE(std::holds_alternative<SceneDef>(load));
  return std::get<SceneDef>(std::move(load));
}

TEST(RenderSnapshot, NormalsOfAFlatSquareAreItsUnitNormal) {
  const std::vector<float> square = {0, 0, 0, 2, 0, 0, 2, 2, 0, 0, 2, 0, 5, 5, 5};
  std::vector<float> normals;
  vertexNormals(square, {{0, 1, 2}, {0, 2, 3}}, normals);
  ASSERT_EQ(normals.size(), square.size());
  for (int v = 0; v < 4; ++v) {
    EXPECT_FLOAT_EQ(normals[3 * v + 2], 1.0f) << v;
  }
  // a vertex on no triangle gets no normal rather than a NaN
  EXPECT_EQ(normals[12], 0.0f);
  EXPECT_EQ(normals[14], 0.0f);
}

TEST(RenderSnapshot, MirrorsTheSceneAndFollowsItThroughAStitch) {
  const SceneDef def = renderSnapshotAnastomosis();
  const Recording rec = scriptedStitch(def);
  Scene scene(def);
  RenderSnapshot snap;
  fillSnapshot(scene, snap);
  const int nodes = static_cast<int>(scene.tissue().nodeCount());
  ASSERT_EQ(snap.tissuePositions.size(), static_cast<std::size_t>(3 * nodes));
  ASSERT_EQ(snap.tissueNormals.size(), snap.tissuePositions.size());
  ASSERT_NE(scene.sutureModel(), nullptr);
  EXPECT_EQ(snap.suturePositions.size(), static_cast<std::size_t>(3 * scene.sutureModel()->nodeCount()));
  EXPECT_EQ(snap.needleNodes, scene.sutureModel()->swage() + 1);
  EXPECT_TRUE(snap.forceps[0].present);
  EXPECT_TRUE(snap.forceps[1].present);

  // outer-surface normals of the vessel point away from its axis
  const SceneVessel& v = def.vessels.front();
  const auto& tri = scene.tissue().triangles()[static_cast<std::size_t>(v.outerSurface.begin)];
  const int c = tri[0];
  const Vec3 p = scene.tissueState().x.col(c);
  const Vec3 axis = v.def.direction.normalized();
  const Vec3 radial = (p - v.def.origin) - (p - v.def.origin).dot(axis) * axis;
  const Vec3 n(snap.tissueNormals[3 * c], snap.tissueNormals[3 * c + 1], snap.tissueNormals[3 * c + 2]);
  EXPECT_NEAR(n.norm(), 1.0, 1e-5);
  EXPECT_GT(n.dot(radial.normalized()), 0.5);

  for (const InputFrame& f : rec.frames) scene.step(f);
  fillSnapshot(scene, snap);
  EXPECT_EQ(snap.steps, scene.steps());
  EXPECT_DOUBLE_EQ(snap.time, scene.time());
  EXPECT_EQ(snap.pierceCount, 4);
  double worst = 0.0;
  for (int i = 0; i < nodes; ++i) {
    for (int d = 0; d < 3; ++d) {
      worst = std::max(worst, std::abs(snap.tissuePositions[3 * i + d] - scene.tissueState().x(d, i)));
    }
  }
  EXPECT_LT(worst, 1e-5);
  const Eigen::Matrix4f pose = scene.forceps(Hand::Right)->pose().matrix().cast<float>();
  EXPECT_TRUE(snap.forceps[1].pose.isApprox(pose));
  for (float f : snap.tissueNormals) ASSERT_TRUE(std::isfinite(f));
}

// a right forceps pointing up (tool +x along the scene's +z), its jaws opening along the
// scene's y, the tip at `tip`
InputFrame uprightRightForceps(const Scene& scene, const Vec3& tip, double closure) {
  InputFrame frame;
  frame.time = scene.time() + scene.dt();
  HandInput& h = frame.hand(Hand::Right);
  h.tracked = true;
  h.position = tip;
  Eigen::Matrix3d r;
  r.col(0) = Vec3::UnitZ();
  r.col(1) = Vec3::UnitY();
  r.col(2) = -Vec3::UnitX();
  h.orientation = Eigen::Quaterniond(r);
  h.closure = closure;
  return frame;
}

TEST(RenderSnapshot, SaysWhatTheOpenJawsWouldCloseOn) {
  const SceneDef def = renderSnapshotAnastomosis();
  Scene scene(def);
  RenderSnapshot snap;
  fillSnapshot(scene, snap);
  const ToolSnapshot& right = snap.forceps[1];

  // in the air
  scene.step(uprightRightForceps(scene, Vec3(-1.5, 0.0, 2.5), 0.0));
  fillSnapshot(scene, snap);
  EXPECT_EQ(right.between, JawTarget::Nothing);
  EXPECT_TRUE(right.betweenPoint.isApprox(Eigen::Vector3f(-1.5f, 0.0f, 2.5f)));

  // astride the top of the wall: the wall, at its top under the tip
  scene.step(uprightRightForceps(scene, Vec3(-1.5, 0.0, 0.45), 0.0));
  fillSnapshot(scene, snap);
  EXPECT_EQ(right.between, JawTarget::Tissue);
  EXPECT_NEAR(right.betweenPoint.x(), -1.5f, 0.15f);
  EXPECT_NEAR(right.betweenPoint.z(), 0.5f, 0.1f);

  // astride a needle node, and then a thread node: the suture, at that node, before any tissue
  for (const int node : {2, snap.needleNodes + 6}) {
    const Vec3 at(snap.suturePositions[3 * node], snap.suturePositions[3 * node + 1], snap.suturePositions[3 * node + 2]);
    scene.step(uprightRightForceps(scene, at - Vec3(0.0, 0.0, 0.05), 0.0));
    fillSnapshot(scene, snap);
    EXPECT_EQ(right.between, node < snap.needleNodes ? JawTarget::Needle : JawTarget::Thread) << node;
    EXPECT_LT((right.betweenPoint.cast<double>() - at).norm(), 0.05) << node;
  }

  // what the snapshot reports is what a grab takes: closing there grips the suture
  scene.step(uprightRightForceps(scene, Vec3(snap.forceps[1].pose(0, 3), snap.forceps[1].pose(1, 3), snap.forceps[1].pose(2, 3)), 1.0));
  fillSnapshot(scene, snap);
  EXPECT_TRUE(right.holdsSuture);
}

TEST(RenderSnapshot, CarriesTheScalpelWhileAHandHoldsIt) {
  SceneDefLoad load = loadSceneDef(kSnapshotTestRoot + "/resources/scenes/single_vessel.json");
  ASSERT_TRUE(std::holds_alternative<SceneDef>(load));
  Scene scene(std::get<SceneDef>(std::move(load)));
  RenderSnapshot snap;
  fillSnapshot(scene, snap);
  EXPECT_FALSE(snap.scalpels[0].present);
  EXPECT_FALSE(snap.scalpels[1].present);

  InputFrame frame;
  frame.time = scene.dt();
  HandInput& h = frame.hand(Hand::Right);
  h.instrument = Instrument::Scalpel;
  h.tracked = true;
  h.position = Vec3(0.5, -0.2, 4.0);
  h.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Vec3::UnitY()));
  scene.step(frame);
  fillSnapshot(scene, snap);
  ASSERT_TRUE(snap.scalpels[1].present);
  EXPECT_FALSE(snap.scalpels[0].present);
  const Eigen::Isometry3d pose = Eigen::Translation3d(h.position) * h.orientation;
  EXPECT_TRUE(snap.scalpels[1].pose.isApprox(pose.matrix().cast<float>()));

  // put down again
  h.instrument = Instrument::Forceps;
  frame.time += scene.dt();
  scene.step(frame);
  fillSnapshot(scene, snap);
  EXPECT_FALSE(snap.scalpels[1].present);
}

TEST(RenderSnapshot, CarriesEachHandsInstrumentAndTheScissorsWhileAHandHoldsThem) {
  Scene scene(renderSnapshotAnastomosis());
  ASSERT_TRUE(scene.def().scissors);
  RenderSnapshot snap;
  fillSnapshot(scene, snap);
  EXPECT_FALSE(snap.scissors[0].present || snap.scissors[1].present);

  InputFrame frame;
  frame.time = scene.dt();
  for (HandInput& hand : frame.hands) hand.tracked = true;
  frame.hand(Hand::Left).position = Vec3(-1.5, 0.0, 3.0);
  HandInput& h = frame.hand(Hand::Right);
  h.instrument = Instrument::Scissors;
  h.position = Vec3(0.5, -0.2, 4.0);
  h.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Vec3::UnitY()));
  h.closure = 0.35;
  scene.step(frame);
  fillSnapshot(scene, snap);
  EXPECT_EQ(snap.instruments[0], Instrument::Forceps);
  EXPECT_EQ(snap.instruments[1], Instrument::Scissors);
  ASSERT_TRUE(snap.scissors[1].present);
  EXPECT_FALSE(snap.scissors[0].present);
  const Eigen::Isometry3d pose = Eigen::Translation3d(h.position) * h.orientation;
  EXPECT_TRUE(snap.scissors[1].pose.isApprox(pose.matrix().cast<float>()));
  EXPECT_DOUBLE_EQ(snap.scissors[1].closure, 0.35);
  const auto blades = tools::scissorsBladePoses(*scene.def().scissors, pose, 0.35);
  for (std::size_t b = 0; b < 2; ++b) EXPECT_TRUE(snap.scissors[1].blades[b].isApprox(blades[b].matrix().cast<float>()));

  // put down again: the forceps is back in the hand
  h.instrument = Instrument::Forceps;
  frame.time += scene.dt();
  scene.step(frame);
  fillSnapshot(scene, snap);
  EXPECT_FALSE(snap.scissors[1].present);
  EXPECT_EQ(snap.instruments[1], Instrument::Forceps);
}

}  // namespace
}  // namespace microsim::sim
