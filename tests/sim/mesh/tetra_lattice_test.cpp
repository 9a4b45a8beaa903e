#include "microsim/sim/mesh/tetra_lattice.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <map>
#include <set>
#include <utility>

namespace microsim::sim {
namespace {

using Edge = std::pair<int, int>;
Edge edge(int a, int b) {
  return {std::min(a, b), std::max(a, b)};
}

TEST(TetraLattice, PaperSizedDefaultCounts) {
  const TetraLatticeDef d;
  EXPECT_EQ(d.nx * d.ny * d.nz, 40880);
  EXPECT_EQ(tetraLatticeLinkCount(d.nx, d.ny, d.nz), 212248);
}

TEST(TetraLattice, LinksAreExactlyTheTetrahedronEdges) {
  TetraLatticeDef d;
  d.nx = 4;
  d.ny = 3;
  d.nz = 5;
  const TetraMesh t = tetraLattice(d);
  const SpringModel& m = t.model;
  EXPECT_EQ(m.nodeCount(), 60);
  EXPECT_EQ(m.linkCount(), tetraLatticeLinkCount(4, 3, 5));
  EXPECT_EQ(t.tetrahedra.size(), 5u * 3u * 2u * 4u);

  std::set<Edge> links;
  for (const Link& l : m.links()) EXPECT_TRUE(links.insert(edge(l.a, l.b)).second);
  std::set<Edge> tetEdges;
  double volume = 0.0;
  const Points& x = m.restPositions();
  for (const auto& tet : t.tetrahedra) {
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) tetEdges.insert(edge(tet[i], tet[j]));
    const Vec3 a = x.col(tet[0]);
    const double v = (x.col(tet[1]) - a).cross(x.col(tet[2]) - a).dot(x.col(tet[3]) - a) / 6.0;
    EXPECT_GT(v, 0.0);
    volume += v;
  }
  EXPECT_EQ(links, tetEdges);
  // the tetrahedra tile the block
  EXPECT_NEAR(volume, 3.0 * 2.0 * 4.0, 1e-12);
}

TEST(TetraLattice, SurfaceIsClosedOutwardAndOnTetrahedronFaces) {
  TetraLatticeDef d;
  d.nx = 3;
  d.ny = 4;
  d.nz = 3;
  d.spacing = 0.5;
  const TetraMesh t = tetraLattice(d);
  const SpringModel& m = t.model;
  const int expected = 2 * 2 * (2 * 3 + 2 * 2 + 3 * 2);
  EXPECT_EQ(static_cast<int>(m.triangles().size()), expected);

  std::set<std::array<int, 3>> tetFaces;
  for (const auto& tet : t.tetrahedra)
    for (int skip = 0; skip < 4; ++skip) {
      std::array<int, 3> f{};
      int k = 0;
      for (int i = 0; i < 4; ++i)
        if (i != skip) f[k++] = tet[i];
      std::sort(f.begin(), f.end());
      tetFaces.insert(f);
    }
  const Vec3 centre(0.5, 0.75, 0.5);
  std::map<Edge, int> directed;
  for (const auto& tri : m.triangles()) {
    std::array<int, 3> s = tri;
    std::sort(s.begin(), s.end());
    EXPECT_TRUE(tetFaces.count(s));
    const Points& x = m.restPositions();
    const Vec3 a = x.col(tri[0]);
    const Vec3 n = (x.col(tri[1]) - a).cross(x.col(tri[2]) - a);
    EXPECT_GT(n.dot((a + x.col(tri[1]) + x.col(tri[2])) / 3.0 - centre), 0.0);
    for (int e = 0; e < 3; ++e) ++directed[{tri[e], tri[(e + 1) % 3]}];
  }
  for (const auto& [e, n] : directed) {
    EXPECT_EQ(n, 1);
    EXPECT_EQ(directed.count({e.second, e.first}), 1u);
  }
  EXPECT_EQ(m.fixedNodes().size(), 12u);
}

}  // namespace
}  // namespace microsim::sim
