// interpenetration: two vessel ends apart have no node inside the other; pushed into each
// other, exactly the nodes that a direct polygon-annulus test puts inside the other end's
// wall are reported, each with the body it is in.
#include "microsim/sim/collide/interpenetration.h"

#include "microsim/sim/scene/scene_def.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>
#include <utility>
#include <variant>

namespace microsim::sim::collide {
namespace {

/// Two 16-sector vessel ends on the x axis, 0.5 mm apart (each 3 mm long, radii 0.5/0.4).
SceneDef interpenetrationTwoEnds() {
  SceneDefLoad load = parseSceneDef(
      R"({"objects": [{"type": "severed-vessel", "gap": 0.5, "axis": [1, 0, 0], "nodes_per_ring": 16}]})");
  EXPECT_TRUE(std::holds_alternative<SceneDef>(load));
  return std::get<SceneDef>(std::move(load));
}

/// Whether p lies inside the undeformed wall of vessel v: between the inner and outer
/// regular P-gons of its cross-section and between its end planes (the shell's triangles
/// are planar quads on a straight vessel, so every cross-section is the same annulus).
bool interpenetrationInsideWall(const SceneVessel& v, const Vec3& p) {
  const Vec3 axis = v.def.direction.normalized();
  const Vec3 e1 = (Vec3::UnitZ() - Vec3::UnitZ().dot(axis) * axis).normalized();
  const Vec3 e2 = axis.cross(e1);
  const Vec3 r = p - v.def.origin;
  const double t = r.dot(axis);
  if (t <= 0.0 || t >= v.def.length) return false;
  const double rho = std::hypot(r.dot(e1), r.dot(e2));
  const double phi = std::atan2(r.dot(e2), r.dot(e1));
  const int n = v.def.nodesPerRing;
  // the largest support along an edge normal: inside the P-gon of circumradius R iff ≤ R cos(π/P)
  double support = -1e300;
  for (int j = 0; j < n; ++j)
    support = std::max(support, rho * std::cos(phi - 2.0 * std::numbers::pi * (j + 0.5) / n));
  const double apothem = std::cos(std::numbers::pi / n);
  return support < v.def.radius * apothem && support > (v.def.radius - v.def.wallThickness) * apothem;
}

TEST(Interpenetration, SeparateEndsHaveNoPairs) {
  const SceneDef def = interpenetrationTwoEnds();
  ASSERT_EQ(def.vessels.size(), 2u);
  const Points x = def.tissue.model.restPositions();
  const Interpenetration r = interpenetration(def.tissue.model, x, def.vessels);
  EXPECT_EQ(r.count, 0);
  EXPECT_TRUE(r.pairs.empty());
}

TEST(Interpenetration, WindingNumberIsOneInTheWallAndZeroInTheLumenAndOutside) {
  const SceneDef def = interpenetrationTwoEnds();
  const std::vector<ClosedBody> bodies = vesselBodies(def.vessels);
  ASSERT_EQ(bodies.size(), 2u);
  EXPECT_EQ(bodies[0].nodeCount, 2 * 7 * 16);
  const Points x = def.tissue.model.restPositions();
  // end 0 runs from x = −3.25 to −0.25
  EXPECT_NEAR(windingNumber(def.tissue.model, x, bodies[0], Vec3(-1.6, 0.0, 0.45)), 1.0, 1e-9);
  EXPECT_NEAR(windingNumber(def.tissue.model, x, bodies[0], Vec3(-1.6, 0.0, 0.0)), 0.0, 1e-9);
  EXPECT_NEAR(windingNumber(def.tissue.model, x, bodies[0], Vec3(-1.6, 0.0, 0.7)), 0.0, 1e-9);
  EXPECT_NEAR(windingNumber(def.tissue.model, x, bodies[0], Vec3(0.0, 0.0, 0.45)), 0.0, 1e-9);
}

TEST(Interpenetration, OverlappingEndsReportExactlyTheNodesInsideTheOtherWall) {
  const SceneDef def = interpenetrationTwoEnds();
  const SpringModel& model = def.tissue.model;
  const std::vector<ClosedBody> bodies = vesselBodies(def.vessels);
  // end 1 pushed 1.4 mm into end 0 (no ring on another's ring plane) and 0.05 mm off axis
  Points x = model.restPositions();
  x.middleCols(bodies[1].firstNode, bodies[1].nodeCount).colwise() += Vec3(-1.4, 0.0, 0.05);

  const Interpenetration r = interpenetration(model, x, def.vessels);
  EXPECT_EQ(r.count, static_cast<int>(r.pairs.size()));
  std::set<std::pair<int, int>> reported;
  for (const PenetratingNode& p : r.pairs) reported.insert({p.node, p.body});
  EXPECT_EQ(reported.size(), r.pairs.size());

  // the direct test, against the undeformed (rigidly moved) walls
  std::set<std::pair<int, int>> expected;
  for (int b = 0; b < 2; ++b) {
    SceneVessel moved = def.vessels[static_cast<std::size_t>(b)];
    if (b == 1) moved.def.origin += Vec3(-1.4, 0.0, 0.05);
    const ClosedBody& other = bodies[static_cast<std::size_t>(1 - b)];
    for (int i = other.firstNode; i < other.firstNode + other.nodeCount; ++i)
      if (interpenetrationInsideWall(moved, x.col(i))) expected.insert({i, b});
  }
  EXPECT_GT(expected.size(), 10u);
  EXPECT_EQ(reported, expected);
  // a body never contains its own nodes
  for (const PenetratingNode& p : r.pairs) {
    const ClosedBody& body = bodies[static_cast<std::size_t>(p.body)];
    EXPECT_FALSE(p.node >= body.firstNode && p.node < body.firstNode + body.nodeCount);
  }
}

}  // namespace
}  // namespace microsim::sim::collide
