// endGapAtStitch: the scene's gap at rest at every angle, the lips at the pierces' mean
// angle, and the distance between them as they move.
#include "microsim/sim/collide/end_gap.h"

#include "microsim/sim/scene/scene_def.h"

#include <gtest/gtest.h>

#include <utility>
#include <variant>

namespace microsim::sim::collide {
namespace {

/// Two 16-sector vessel ends on the x axis, 0.5 mm apart.
SceneDef endGapTwoEnds() {
  SceneDefLoad load = parseSceneDef(
      R"({"objects": [{"type": "severed-vessel", "gap": 0.5, "axis": [1, 0, 0], "nodes_per_ring": 16}]})");
  EXPECT_TRUE(std::holds_alternative<SceneDef>(load));
  return std::get<SceneDef>(std::move(load));
}

TEST(EndGap, AtRestTheGapIsTheScenesWhereverTheStitchIs) {
  const SceneDef def = endGapTwoEnds();
  const Points x = def.tissue.model.restPositions();
  for (const Vec3& pierce : {Vec3(-0.3, 0.6, 0.0), Vec3(0.2, 0.0, -0.5), Vec3(0.0, -0.4, 0.4)}) {
    const auto g = endGapAtStitch(def.tissue.model, x, def.vessels, {pierce});
    ASSERT_TRUE(g.has_value());
    EXPECT_NEAR(g->gap, 0.5, 1e-12);
    EXPECT_NEAR(g->restGap, 0.5, 1e-12);
    // both lips at the pierce's angle, on the outer hull of the cut ring
    const Vec3 lip0 = x.col(g->node0), lip1 = x.col(g->node1);
    EXPECT_NEAR(lip0.x(), -0.25, 1e-12);
    EXPECT_NEAR(lip1.x(), 0.25, 1e-12);
    const Vec3 radial(0.0, pierce.y(), pierce.z());
    EXPECT_NEAR(Vec3(0.0, lip0.y(), lip0.z()).normalized().dot(radial.normalized()), 1.0, 1e-9);
    EXPECT_NEAR(Vec3(0.0, lip1.y(), lip1.z()).norm(), 0.5, 1e-12);
  }
}

TEST(EndGap, TheStitchAngleIsThePiercesMeanDirection) {
  const SceneDef def = endGapTwoEnds();
  const Points x = def.tissue.model.restPositions();
  // pierces at +y and +z, at different radii and positions along the axis: 45° between
  const auto g = endGapAtStitch(def.tissue.model, x, def.vessels, {Vec3(-0.4, 0.45, 0.0), Vec3(0.3, 0.0, 0.9)});
  ASSERT_TRUE(g.has_value());
  EXPECT_NEAR(g->direction.dot(Vec3(0.0, 1.0, 1.0).normalized()), 1.0, 1e-12);
  EXPECT_NEAR(x(1, g->node0), x(2, g->node0), 1e-12);
  EXPECT_GT(x(1, g->node0), 0.3);
  EXPECT_NEAR(x(1, g->node1), x(2, g->node1), 1e-12);
}

TEST(EndGap, TheGapFollowsTheLips) {
  const SceneDef def = endGapTwoEnds();
  Points x = def.tissue.model.restPositions();
  const auto atRest = endGapAtStitch(def.tissue.model, x, def.vessels, {Vec3(0.0, 0.6, 0.0)});
  ASSERT_TRUE(atRest.has_value());
  // end 1's lip drawn 0.2 mm away, then end 0's lip 0.4 mm towards it and 0.4 mm sideways
  x(0, atRest->node1) += 0.2;
  EXPECT_NEAR(endGapAtStitch(def.tissue.model, x, def.vessels, {Vec3(0.0, 0.6, 0.0)})->gap, 0.7, 1e-12);
  x(0, atRest->node0) += 0.4;
  x(2, atRest->node0) += 0.4;
  EXPECT_NEAR(endGapAtStitch(def.tissue.model, x, def.vessels, {Vec3(0.0, 0.6, 0.0)})->gap, 0.5, 1e-12);
}

TEST(EndGap, NoPierceMeansSectorZeroAndNoEndsMeansNoGap) {
  const SceneDef def = endGapTwoEnds();
  const Points x = def.tissue.model.restPositions();
  const auto g = endGapAtStitch(def.tissue.model, x, def.vessels, {});
  ASSERT_TRUE(g.has_value());
  EXPECT_NEAR(g->direction.dot(Vec3::UnitZ()), 1.0, 1e-12);
  EXPECT_NEAR(g->gap, 0.5, 1e-12);

  SceneDefLoad single = parseSceneDef(R"({"objects": [{"type": "vessel"}]})");
  ASSERT_TRUE(std::holds_alternative<SceneDef>(single));
  const SceneDef& one = std::get<SceneDef>(single);
  EXPECT_FALSE(endGapAtStitch(one.tissue.model, one.tissue.model.restPositions(), one.vessels, {}).has_value());
}

}  // namespace
}  // namespace microsim::sim::collide
