#include "microsim/sim/mesh/lattice.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <set>
#include <utility>

namespace microsim::sim {
namespace {

TEST(Lattice, LinkCountsMatchThePaper) {
  // Table 1 of Brown et al. 2002
  const std::pair<int, int> table[] = {{6, 1440}, {8, 3696}, {10, 7560}, {15, 27090}, {20, 66120}};
  for (auto [n, links] : table) {
    EXPECT_EQ(latticeLinkCount(n), links) << n;
    const SpringModel m = latticeBox(n);
    EXPECT_EQ(m.nodeCount(), n * n * n) << n;
    EXPECT_EQ(m.linkCount(), links) << n;
  }
}

TEST(Lattice, SmallBoxCount) {
  // the paper's text lists 64 links for 3³, which no reading of its rule gives; the
  // rule that reproduces all five Table 1 counts gives 54 + 72
  EXPECT_EQ(latticeBox(3).linkCount(), 126);
  EXPECT_EQ(latticeBox(2).linkCount(), 12 + 12);
}

TEST(Lattice, LinksAreUniqueAxisOrFaceDiagonals) {
  const SpringModel m = latticeBox(4, 7.5);
  std::set<std::pair<int, int>> seen;
  for (const Link& l : m.links()) {
    EXPECT_TRUE(seen.insert({std::min(l.a, l.b), std::max(l.a, l.b)}).second);
    const Vec3 d = (m.restPositions().col(l.a) - m.restPositions().col(l.b)).cwiseAbs();
    const int nonzero = (d.array() > 0.5).count();
    EXPECT_TRUE(nonzero == 1 || nonzero == 2);
    EXPECT_LE(d.maxCoeff(), 1.0 + 1e-12);
    EXPECT_NEAR(l.rest, d.norm(), 1e-12);
    EXPECT_EQ(l.k, 7.5);
    EXPECT_TRUE(l.alive);
  }
}

TEST(Lattice, BottomFaceFixedMassesOne) {
  const int n = 5;
  const SpringModel m = latticeBox(n);
  const std::vector<int> fixed = m.fixedNodes();
  EXPECT_EQ(static_cast<int>(fixed.size()), n * n);
  for (int i : fixed) EXPECT_EQ(m.restPositions()(2, i), 0.0);
  for (int i = 0; i < m.nodeCount(); ++i) EXPECT_EQ(m.mass(i), 1.0);
  EXPECT_TRUE(m.finalized());
}

TEST(Lattice, TopMiddleNode) {
  for (int n : {3, 4, 6, 7}) {
    const SpringModel m = latticeBox(n);
    const Vec3 p = m.restPositions().col(latticeTopMiddle(n));
    const int middle = n / 2;  // the middle node's grid index, rounded down for even n
    EXPECT_EQ(p, Vec3(middle, middle, n - 1)) << n;
    EXPECT_FALSE(m.isFixed(latticeTopMiddle(n)));
  }
}

TEST(Lattice, SurfaceTrianglesCloseTheBoxOutward) {
  const int n = 4;
  const SpringModel m = latticeBox(n);
  EXPECT_EQ(static_cast<int>(m.triangles().size()), 6 * 2 * (n - 1) * (n - 1));
  // closed: every edge is shared by exactly two triangles, in opposite directions
  std::set<std::pair<int, int>> directed;
  const Vec3 centre = Vec3::Constant((n - 1) / 2.0);
  for (const auto& t : m.triangles()) {
    for (int e = 0; e < 3; ++e) EXPECT_TRUE(directed.insert({t[e], t[(e + 1) % 3]}).second);
    const Vec3 a = m.restPositions().col(t[0]);
    const Vec3 b = m.restPositions().col(t[1]);
    const Vec3 c = m.restPositions().col(t[2]);
    const Vec3 normal = (b - a).cross(c - a);
    EXPECT_GT(normal.dot((a + b + c) / 3.0 - centre), 0.0);
  }
  for (auto [a, b] : directed) EXPECT_TRUE(directed.count({b, a}));
}

TEST(Lattice, AdjacencyCoversEveryLinkTwice) {
  const SpringModel m = latticeBox(3);
  int total = 0;
  for (int i = 0; i < m.nodeCount(); ++i) total += static_cast<int>(m.linksOf(i).size());
  EXPECT_EQ(total, 2 * m.linkCount());
}

}  // namespace
}  // namespace microsim::sim
