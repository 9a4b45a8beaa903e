#include "microsim/sim/mesh/grid.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <set>
#include <utility>

namespace microsim::sim {
namespace {

TEST(Grid, CollisionBenchmarkSizes) {
  const SpringModel big = gridMesh(100, 100, 1.0);
  EXPECT_EQ(big.triangles().size(), 20000u);
  EXPECT_EQ(big.nodeCount(), 101 * 101);
  EXPECT_EQ(big.linkCount(), 3 * 100 * 100 + 200);
  const SpringModel plane = gridMesh(64, 64, 0.125);
  EXPECT_EQ(plane.triangles().size(), 8192u);
  const Points& x = plane.restPositions();
  EXPECT_DOUBLE_EQ(x.row(0).minCoeff(), -4.0);
  EXPECT_DOUBLE_EQ(x.row(0).maxCoeff(), 4.0);
  EXPECT_DOUBLE_EQ(x.row(1).maxCoeff(), 4.0);
  EXPECT_EQ(x.row(2).cwiseAbs().maxCoeff(), 0.0);
}

TEST(Grid, LinksAreUniqueTriangleEdgesAndNormalsFaceUp) {
  const SpringModel m = gridMesh(3, 2, 0.5);
  std::set<std::pair<int, int>> links;
  for (const Link& l : m.links()) {
    EXPECT_TRUE(links.insert({std::min(l.a, l.b), std::max(l.a, l.b)}).second);
    EXPECT_EQ(l.k, 10.0);
  }
  std::set<std::pair<int, int>> edges;
  for (const auto& t : m.triangles()) {
    for (int e = 0; e < 3; ++e)
      edges.insert({std::min(t[e], t[(e + 1) % 3]), std::max(t[e], t[(e + 1) % 3])});
    const Vec3 a = m.restPositions().col(t[0]);
    const Vec3 n = (m.restPositions().col(t[1]) - a).cross(m.restPositions().col(t[2]) - a);
    EXPECT_NEAR(n.z(), 0.25, 1e-12);
  }
  EXPECT_EQ(links, edges);
  EXPECT_TRUE(m.fixedNodes().empty());
}

TEST(Grid, FixBorder) {
  GridDef d;
  d.cellsX = 4;
  d.cellsY = 3;
  d.fixBorder = true;
  const SpringModel m = gridMesh(d);
  EXPECT_EQ(m.fixedNodes().size(), 5u * 4u - 3u * 2u);
  EXPECT_FALSE(m.isFixed(gridIndex(4, 2, 1)));
  EXPECT_TRUE(m.isFixed(gridIndex(4, 4, 1)));
}

}  // namespace
}  // namespace microsim::sim
