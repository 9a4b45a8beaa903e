#include "microsim/sim/mesh/smooth_surface.h"

#include "microsim/sim/mesh/vessel.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

namespace microsim::sim {
namespace {

// one end of the default scene's vessel: 7 rings of 16 nodes per hull, 1 mm across
VesselMesh sceneVessel() {
  VesselDef d;
  d.nodesPerRing = 16;
  return vessel(d);
}

Points placed(const SmoothSurface& s, const Points& nodes) {
  Points out;
  s.place(nodes, out);
  return out;
}

double distanceFromAxis(const Vec3& p) {
  return std::hypot(p.y(), p.z());
}

std::set<int> refinedVerticesOf(const SmoothSurface& s, TriangleRange coarse) {
  std::set<int> out;
  for (std::size_t t = 0; t < s.triangles().size(); ++t) {
    const int parent = s.parentTriangles()[t];
    if (parent >= coarse.begin && parent < coarse.end)
      out.insert(s.triangles()[t].begin(), s.triangles()[t].end());
  }
  return out;
}

TEST(SmoothSurface, EachLevelHasFourTimesTheTrianglesAndTheSurfacePassesThroughEveryNode) {
  const VesselMesh v = sceneVessel();
  const auto& rest = v.model.restPositions();
  for (int levels : {1, 2}) {
    const auto s = SmoothSurface::build(v.model.triangles(), rest, levels);
    ASSERT_TRUE(s.has_value());
    EXPECT_EQ(s->triangles().size(), v.model.triangles().size() << (2 * levels));
    const Points refined = placed(*s, rest);
    ASSERT_EQ(refined.cols(), s->vertexCount());
    for (int n = 0; n < v.model.nodeCount(); ++n) {
      const int at = s->nodeVertices()[static_cast<std::size_t>(n)];
      ASSERT_GE(at, 0);
      EXPECT_LT((refined.col(at) - rest.col(n)).norm(), 1e-9) << "node " << n;
    }
  }
}

TEST(SmoothSurface, TheOuterWallIsRoundWhereTheCoarseTrianglesCutTheCircle) {
  const VesselMesh v = sceneVessel();
  const auto s = SmoothSurface::build(v.model.triangles(), v.model.restPositions(), 2);
  ASSERT_TRUE(s.has_value());
  const Points refined = placed(*s, v.model.restPositions());
  // a flat triangle's mid-edge between two of the 16 sectors lies cos(π/16) of the radius out
  const double flatGap = 1.0 - std::cos(std::numbers::pi / 16.0);
  ASSERT_GT(flatGap, 0.019);
  double worst = 0.0;
  for (int vertex : refinedVerticesOf(*s, v.outerSurface))
    worst = std::max(worst, std::abs(distanceFromAxis(refined.col(vertex)) / v.def.radius - 1.0));
  EXPECT_LT(worst, 0.1 * flatGap);
}

TEST(SmoothSurface, TheCutFaceStaysFlatAndItsRimsStayCreases) {
  const VesselMesh v = sceneVessel();
  const auto s = SmoothSurface::build(v.model.triangles(), v.model.restPositions(), 2);
  ASSERT_TRUE(s.has_value());
  const Points refined = placed(*s, v.model.restPositions());
  const double cutPlane = v.def.length;
  const double inner = v.def.radius - v.def.wallThickness;
  for (int vertex : refinedVerticesOf(*s, v.cutEnd)) {
    EXPECT_NEAR(refined(0, vertex), cutPlane, 1e-9);
    // the face keeps the wall's thickness: nothing rounds its rims inwards
    const double r = distanceFromAxis(refined.col(vertex));
    EXPECT_GE(r, inner * (1.0 - 1e-3));
    EXPECT_LE(r, v.def.radius * (1.0 + 1e-3));
  }
}

TEST(SmoothSurface, AMovedNodeCarriesTheSurfaceThroughItsNewPlaceAndLeavesFarTissueAlone) {
  const VesselMesh v = sceneVessel();
  const auto s = SmoothSurface::build(v.model.triangles(), v.model.restPositions(), 2);
  ASSERT_TRUE(s.has_value());
  const Points before = placed(*s, v.model.restPositions());
  Points moved = v.model.restPositions();
  const int pulled = v.node(VesselHull::Outer, 3, 4);
  moved.col(pulled) += Vec3(0.0, 0.0, 0.2);
  const Points after = placed(*s, moved);
  EXPECT_LT(
      (after.col(s->nodeVertices()[static_cast<std::size_t>(pulled)]) - moved.col(pulled)).norm(),
      1e-9);
  // the other nodes stay exactly where they are, and the clamped end barely feels it
  for (int n = 0; n < v.model.nodeCount(); ++n) {
    if (n == pulled) continue;
    EXPECT_LT((after.col(s->nodeVertices()[static_cast<std::size_t>(n)]) - moved.col(n)).norm(),
              1e-9);
  }
  for (int vertex : refinedVerticesOf(*s, v.clampedEnd))
    EXPECT_LT((after.col(vertex) - before.col(vertex)).norm(), 0.01 * 0.2);
  // and the float path gives the same surface
  std::vector<float> nodes(3 * static_cast<std::size_t>(moved.cols()));
  for (Eigen::Index n = 0; n < moved.cols(); ++n)
    for (Eigen::Index c = 0; c < 3; ++c)
      nodes[static_cast<std::size_t>(3 * n + c)] = static_cast<float>(moved(c, n));
  std::vector<float> out;
  s->place(nodes.data(), out);
  ASSERT_EQ(out.size(), 3 * static_cast<std::size_t>(after.cols()));
  for (Eigen::Index vertex = 0; vertex < after.cols(); ++vertex)
    for (Eigen::Index c = 0; c < 3; ++c)
      EXPECT_NEAR(out[static_cast<std::size_t>(3 * vertex + c)], after(c, vertex), 1e-5);
}

TEST(SmoothSurface, ABlendOfColoursStaysWithinTheColoursBlended) {
  const VesselMesh v = sceneVessel();
  const auto s = SmoothSurface::build(v.model.triangles(), v.model.restPositions(), 2);
  ASSERT_TRUE(s.has_value());
  // a constant stays that constant; a colour that is 1 on one ring and 0 elsewhere stays in [0, 1]
  std::vector<float> perNode(2 * static_cast<std::size_t>(v.model.nodeCount()));
  for (int n = 0; n < v.model.nodeCount(); ++n) {
    perNode[2 * static_cast<std::size_t>(n)] = 0.25f;
    perNode[2 * static_cast<std::size_t>(n) + 1] =
        v.ring[static_cast<std::size_t>(n)] == 3 ? 1.0f : 0.0f;
  }
  std::vector<float> out;
  s->blend(perNode, 2, out);
  ASSERT_EQ(out.size(), 2 * static_cast<std::size_t>(s->vertexCount()));
  float highest = 0.0f;
  for (int vertex = 0; vertex < s->vertexCount(); ++vertex) {
    EXPECT_NEAR(out[2 * static_cast<std::size_t>(vertex)], 0.25f, 1e-6f);
    const float ringThree = out[2 * static_cast<std::size_t>(vertex) + 1];
    EXPECT_GE(ringThree, -1e-6f);
    EXPECT_LE(ringThree, 1.0f + 1e-6f);
    highest = std::max(highest, ringThree);
  }
  EXPECT_GT(highest, 0.5f);
}

TEST(SmoothSurface, RefusesWhatItCannotRefineAndSaysWhy) {
  const VesselMesh v = sceneVessel();
  SmoothSurfaceError why = SmoothSurfaceError::None;
  EXPECT_FALSE(SmoothSurface::build({}, v.model.restPositions(), 2, &why).has_value());
  EXPECT_EQ(why, SmoothSurfaceError::NoTriangles);
  EXPECT_FALSE(
      SmoothSurface::build(v.model.triangles(), v.model.restPositions(), 0, &why).has_value());
  EXPECT_EQ(why, SmoothSurfaceError::BadLevels);
  EXPECT_FALSE(SmoothSurface::build(v.model.triangles(), v.model.restPositions(),
                                    kMaxSmoothLevels + 1, &why));
  EXPECT_EQ(why, SmoothSurfaceError::BadLevels);
  std::vector<std::array<int, 3>> outOfRange = v.model.triangles();
  outOfRange.front()[1] = v.model.nodeCount();
  EXPECT_FALSE(SmoothSurface::build(outOfRange, v.model.restPositions(), 2, &why).has_value());
  EXPECT_EQ(why, SmoothSurfaceError::BadTopology);
}

}  // namespace
}  // namespace microsim::sim
