#include "microsim/sim/collide/point_triangle.h"

#include "sim/collide/brute_force.h"

#include <gtest/gtest.h>

namespace microsim::sim::collide {
namespace {

using brute::cubePoint;
using Eigen::Vector3d;
using brute::hullDistance;
using brute::latticePoint;

void expectPointTriangleMatchesBruteForce(const Vector3d& p, const Vector3d& a, const Vector3d& b,
                             const Vector3d& c) {
  const PointTriangleClosest got = closestPointTriangle(p, a, b, c);
  const double want = hullDistance({p}, {a, b, c});
  ASSERT_NEAR(got.distance, want, 1e-9) << p.transpose() << " | " << a.transpose() << " | "
                                        << b.transpose() << " | " << c.transpose();
  EXPECT_GE(got.barycentric.minCoeff(), -1e-12);
  EXPECT_NEAR(got.barycentric.sum(), 1.0, 1e-12);
  const Vector3d rebuilt = got.barycentric[0] * a + got.barycentric[1] * b + got.barycentric[2] * c;
  EXPECT_LT((rebuilt - got.point).norm(), 1e-9);
  EXPECT_NEAR((p - got.point).norm(), got.distance, 1e-12);
}

TEST(PointTriangle, RandomCasesMatchBruteForce) {
  std::mt19937 rng(7);
  for (int i = 0; i < 3000; ++i)
    expectPointTriangleMatchesBruteForce(2.0 * cubePoint(rng), cubePoint(rng), cubePoint(rng), cubePoint(rng));
}

TEST(PointTriangle, LatticeCasesMatchBruteForce) {
  // coplanar points, points on edges and corners, zero-area triangles
  std::mt19937 rng(8);
  for (int i = 0; i < 3000; ++i)
    expectPointTriangleMatchesBruteForce(latticePoint(rng), latticePoint(rng), latticePoint(rng),
                            latticePoint(rng));
}

TEST(PointTriangle, DegenerateTriangles) {
  const Vector3d o(0, 0, 0), x(1, 0, 0), y(0, 1, 0);
  // collinear corners: the closest point of the longest edge
  expectPointTriangleMatchesBruteForce(Vector3d(0.5, 1, 0), o, x, Vector3d(2, 0, 0));
  // all corners coincide
  const PointTriangleClosest point = closestPointTriangle(Vector3d(0, 0, 2), x, x, x);
  EXPECT_DOUBLE_EQ(point.distance, std::sqrt(5.0));
  // a point on the face
  const PointTriangleClosest face = closestPointTriangle(Vector3d(0.25, 0.25, 0), o, x, y);
  EXPECT_DOUBLE_EQ(face.distance, 0.0);
  EXPECT_NEAR(face.barycentric[1], 0.25, 1e-15);
  EXPECT_NEAR(face.barycentric[2], 0.25, 1e-15);
}

}  // namespace
}  // namespace microsim::sim::collide
