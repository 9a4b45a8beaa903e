#include "microsim/sim/mesh/vessel.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>

namespace microsim::sim {
namespace {

Vec3 triangleNormal(const SpringModel& m, const std::array<int, 3>& t) {
  const Vec3 a = m.restPositions().col(t[0]);
  return (m.restPositions().col(t[1]) - a).cross(m.restPositions().col(t[2]) - a);
}

Vec3 triangleCentre(const SpringModel& m, const std::array<int, 3>& t) {
  return (m.restPositions().col(t[0]) + m.restPositions().col(t[1]) + m.restPositions().col(t[2])) /
         3.0;
}

TEST(Vessel, PaperDefaultHas98NodesAnd581Links) {
  const VesselMesh v = vessel();
  EXPECT_EQ(v.model.nodeCount(), 98);
  EXPECT_EQ(v.model.linkCount(), 581);
  EXPECT_EQ(vesselLinkCount(7, 7), 581);
  EXPECT_TRUE(v.model.finalized());
}

TEST(Vessel, FinePresetNear10kNodes) {
  const VesselDef d = VesselDef::fine();
  EXPECT_EQ(2 * d.rings * d.nodesPerRing, 9940);
  EXPECT_EQ(vesselLinkCount(d.rings, d.nodesPerRing), 64050);
  const VesselMesh v = vessel(d);
  EXPECT_EQ(v.model.nodeCount(), 9940);
  EXPECT_EQ(v.model.linkCount(), 64050);
}

TEST(Vessel, GeometryAndPerNodeTags) {
  VesselDef d;
  d.rings = 4;
  d.nodesPerRing = 6;
  const VesselMesh v = vessel(d);
  ASSERT_EQ(v.model.nodeCount(), 48);
  EXPECT_EQ(v.model.linkCount(), vesselLinkCount(4, 6));
  for (int i = 0; i < v.model.nodeCount(); ++i) {
    const Vec3 p = v.model.restPositions().col(i);
    const double r = std::hypot(p.y(), p.z());
    const double expected = v.hull[i] == VesselHull::Outer ? 0.5 : 0.4;
    EXPECT_NEAR(r, expected, 1e-12) << i;
    EXPECT_NEAR(p.x(), 3.0 * v.ring[i] / 3.0, 1e-12) << i;
    EXPECT_EQ(v.node(v.hull[i], v.ring[i], v.sector[i]), i);
    EXPECT_EQ(v.model.isFixed(i), v.ring[i] == 0) << i;
    EXPECT_EQ(v.model.mass(i), 1.0);
  }
  // sector 0 lies on +z (the reference direction) for an axis along x
  EXPECT_NEAR(v.model.restPositions()(2, v.node(VesselHull::Outer, 2, 0)), 0.5, 1e-12);
  EXPECT_EQ(static_cast<int>(v.cutEdgeNodes().size()), 12);
  for (int i : v.cutEdgeNodes()) EXPECT_EQ(v.ring[i], 3);
}

TEST(Vessel, StiffnessWithinAndBetweenLayersAndNoDuplicates) {
  const VesselMesh v = vessel();
  std::set<std::pair<int, int>> seen;
  int within = 0;
  int between = 0;
  for (const Link& l : v.model.links()) {
    EXPECT_NE(l.a, l.b);
    EXPECT_TRUE(seen.insert({std::min(l.a, l.b), std::max(l.a, l.b)}).second);
    if (v.ring[l.a] == v.ring[l.b]) {
      EXPECT_EQ(l.k, 50.0);
      ++within;
    } else {
      EXPECT_EQ(std::abs(v.ring[l.a] - v.ring[l.b]), 1);
      EXPECT_EQ(l.k, 100.0);
      ++between;
    }
    EXPECT_GT(l.rest, 0.0);
  }
  EXPECT_EQ(within, 5 * 7 * 7);
  EXPECT_EQ(between, 8 * 6 * 7);
}

TEST(Vessel, SurfacesAreClosedAndWoundOutOfTheWall) {
  VesselDef d;
  d.direction = Vec3(1, 2, 3);
  d.origin = Vec3(5, -1, 2);
  const VesselMesh v = vessel(d);
  const SpringModel& m = v.model;
  const Vec3 axis = d.direction.normalized();
  const int quads = (d.rings - 1) * d.nodesPerRing;
  EXPECT_EQ(v.outerSurface.size(), 2 * quads);
  EXPECT_EQ(v.innerSurface.size(), 2 * quads);
  EXPECT_EQ(v.clampedEnd.size(), 2 * d.nodesPerRing);
  EXPECT_EQ(v.cutEnd.size(), 2 * d.nodesPerRing);
  EXPECT_EQ(v.cutEnd.end, static_cast<int>(m.triangles().size()));

  auto radial = [&](const Vec3& p) {
    const Vec3 q = p - d.origin;
    return Vec3(q - q.dot(axis) * axis);
  };
  for (int t = v.outerSurface.begin; t < v.outerSurface.end; ++t) {
    const auto& tri = m.triangles()[t];
    EXPECT_GT(triangleNormal(m, tri).dot(radial(triangleCentre(m, tri))), 0.0);
  }
  for (int t = v.innerSurface.begin; t < v.innerSurface.end; ++t) {
    const auto& tri = m.triangles()[t];
    EXPECT_LT(triangleNormal(m, tri).dot(radial(triangleCentre(m, tri))), 0.0);
  }
  for (int t = v.clampedEnd.begin; t < v.clampedEnd.end; ++t)
    EXPECT_LT(triangleNormal(m, m.triangles()[t]).dot(axis), 0.0);
  for (int t = v.cutEnd.begin; t < v.cutEnd.end; ++t)
    EXPECT_GT(triangleNormal(m, m.triangles()[t]).dot(axis), 0.0);

  // the whole wall surface is closed and consistently oriented
  std::map<std::pair<int, int>, int> directed;
  for (const auto& tri : m.triangles())
    for (int e = 0; e < 3; ++e) ++directed[{tri[e], tri[(e + 1) % 3]}];
  for (const auto& [edge, n] : directed) {
    EXPECT_EQ(n, 1);
    EXPECT_EQ(directed.count({edge.second, edge.first}), 1u);
  }
}

TEST(Vessel, ValidatesDefs) {
  EXPECT_TRUE(validVesselDef(VesselDef::paper()));
  EXPECT_TRUE(validVesselDef(VesselDef::fine()));
  VesselDef d;
  d.wallThickness = 0.5;
  EXPECT_FALSE(validVesselDef(d));
  d = {};
  d.rings = 1;
  EXPECT_FALSE(validVesselDef(d));
  d = {};
  d.length = std::nan("");
  EXPECT_FALSE(validVesselDef(d));
  d = {};
  d.direction = Vec3::Zero();
  EXPECT_FALSE(validVesselDef(d));
  d = {};
  d.kLayer = -1;
  EXPECT_FALSE(validVesselDef(d));
}

}  // namespace
}  // namespace microsim::sim
