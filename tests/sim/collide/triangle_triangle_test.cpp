#include "microsim/sim/collide/triangle_triangle.h"

#include "sim/collide/brute_force.h"

#include <gtest/gtest.h>

namespace microsim::sim::collide {
namespace {

using brute::cubePoint;
using Eigen::Vector3d;
using brute::hullDistance;
using brute::latticePoint;

bool expectTriangleTriangleMatchesBruteForce(const std::array<Vector3d, 6>& v) {
  const bool got = trianglesIntersect(v[0], v[1], v[2], v[3], v[4], v[5]);
  const double want = hullDistance({v[0], v[1], v[2]}, {v[3], v[4], v[5]});
  EXPECT_EQ(got, want < 1e-9) << "distance " << want << ": " << v[0].transpose() << " | "
                              << v[1].transpose() << " | " << v[2].transpose() << " || "
                              << v[3].transpose() << " | " << v[4].transpose() << " | "
                              << v[5].transpose();
  EXPECT_NEAR(triangleTriangleDistance(v[0], v[1], v[2], v[3], v[4], v[5]), want, 1e-9);
  // symmetric
  EXPECT_EQ(trianglesIntersect(v[3], v[4], v[5], v[0], v[1], v[2]), got);
  return got;
}

TEST(TriangleTriangle, RandomCasesMatchBruteForce) {
  std::mt19937 rng(31);
  int hits = 0;
  for (int i = 0; i < 3000; ++i) {
    const Vector3d shift = 0.8 * cubePoint(rng);
    hits += expectTriangleTriangleMatchesBruteForce({cubePoint(rng), cubePoint(rng), cubePoint(rng),
                                     shift + cubePoint(rng), shift + cubePoint(rng),
                                     shift + cubePoint(rng)});
  }
  EXPECT_GT(hits, 300);
  EXPECT_LT(hits, 2700);
}

TEST(TriangleTriangle, LatticeCasesMatchBruteForce) {
  // coplanar, parallel, touching, zero-area and collapsed triangles
  std::mt19937 rng(32);
  int hits = 0;
  for (int i = 0; i < 3000; ++i) {
    std::array<Vector3d, 6> v;
    for (Vector3d& p : v) p = latticePoint(rng);
    hits += expectTriangleTriangleMatchesBruteForce(v);
  }
  EXPECT_GT(hits, 300);
}

TEST(TriangleTriangle, CoplanarFlatCases) {
  // all in z = 0: overlapping, nested, touching at a corner, disjoint
  std::mt19937 rng(33);
  std::uniform_int_distribution<int> pick(-3, 3);
  for (int i = 0; i < 2000; ++i) {
    std::array<Vector3d, 6> v;
    for (Vector3d& p : v) p = Vector3d(pick(rng), pick(rng), 0);
    expectTriangleTriangleMatchesBruteForce(v);
  }
}

TEST(TriangleTriangle, NamedCases) {
  const Vector3d a(0, 0, 0), b(4, 0, 0), c(0, 4, 0);
  // one inside the other, coplanar
  EXPECT_TRUE(trianglesIntersect(a, b, c, Vector3d(1, 1, 0), Vector3d(2, 1, 0), Vector3d(1, 2, 0)));
  // parallel planes
  EXPECT_FALSE(trianglesIntersect(a, b, c, Vector3d(0, 0, 1), Vector3d(4, 0, 1), Vector3d(0, 4, 1)));
  // a corner touching the face
  EXPECT_TRUE(trianglesIntersect(a, b, c, Vector3d(1, 1, 0), Vector3d(1, 1, 2), Vector3d(2, 1, 2)));
  // crossing through the face
  EXPECT_TRUE(trianglesIntersect(a, b, c, Vector3d(1, 1, -1), Vector3d(1, 1, 1), Vector3d(5, 5, 1)));
  // a collapsed triangle (a point) on the face and off it
  const Vector3d on(1, 1, 0), off(1, 1, 0.1);
  EXPECT_TRUE(trianglesIntersect(a, b, c, on, on, on));
  EXPECT_FALSE(trianglesIntersect(a, b, c, off, off, off));
  EXPECT_DOUBLE_EQ(triangleTriangleDistance(a, b, c, off, off, off), 0.1);
}

}  // namespace
}  // namespace microsim::sim::collide
