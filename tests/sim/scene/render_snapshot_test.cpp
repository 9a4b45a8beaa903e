// The snapshot the viewport draws: it mirrors the scene's state after a step (positions,
// unit normals pointing out of the wall, the suture, the forceps' poses), and refilling it
// follows the scene as it moves.
#include "microsim/sim/scene/render_snapshot.h"

#include "microsim/sim/scene/scene.h"
#include "microsim/sim/scene/stitch_script.h"

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

}  // namespace
}  // namespace microsim::sim
