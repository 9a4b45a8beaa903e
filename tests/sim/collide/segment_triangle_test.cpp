#include "microsim/sim/collide/segment_triangle.h"

#include "sim/collide/brute_force.h"

#include <gtest/gtest.h>

namespace microsim::sim::collide {
namespace {

using brute::cubePoint;
using Eigen::Vector3d;
using brute::hullDistance;
using brute::latticePoint;

// returns whether it hit, for coverage counts
bool expectSegmentTriangleMatchesBruteForce(const Vector3d& p, const Vector3d& q, const Vector3d& a,
                             const Vector3d& b, const Vector3d& c) {
  const std::optional<SegmentTriangleHit> hit = intersectSegmentTriangle(p, q, a, b, c);
  const double want = hullDistance({p, q}, {a, b, c});
  EXPECT_EQ(hit.has_value(), want < 1e-9)
      << "distance " << want << ": " << p.transpose() << " | " << q.transpose() << " | "
      << a.transpose() << " | " << b.transpose() << " | " << c.transpose();
  EXPECT_NEAR(segmentTriangleDistance(p, q, a, b, c), want, 1e-9);
  if (!hit) return false;

  // the hit lies on the segment at t and in the triangle at its barycentrics
  EXPECT_GE(hit->t, 0.0);
  EXPECT_LE(hit->t, 1.0);
  EXPECT_GE(hit->barycentric.minCoeff(), -1e-12);
  EXPECT_NEAR(hit->barycentric.sum(), 1.0, 1e-12);
  const Vector3d onTriangle =
      hit->barycentric[0] * a + hit->barycentric[1] * b + hit->barycentric[2] * c;
  EXPECT_LT((onTriangle - hit->point).norm(), 1e-9);
  EXPECT_LT((p + hit->t * (q - p) - hit->point).norm(), 1e-9);
  return true;
}

TEST(SegmentTriangle, RandomCasesMatchBruteForce) {
  std::mt19937 rng(21);
  int hits = 0;
  for (int i = 0; i < 4000; ++i)
    hits += expectSegmentTriangleMatchesBruteForce(1.5 * cubePoint(rng), 1.5 * cubePoint(rng), cubePoint(rng),
                                    cubePoint(rng), cubePoint(rng));
  EXPECT_GT(hits, 100);
  EXPECT_LT(hits, 3900);
}

TEST(SegmentTriangle, LatticeCasesMatchBruteForce) {
  // coplanar, parallel, touching at corners and edges, zero-area triangles, zero-length segments
  std::mt19937 rng(22);
  int hits = 0;
  for (int i = 0; i < 6000; ++i)
    hits += expectSegmentTriangleMatchesBruteForce(latticePoint(rng), latticePoint(rng), latticePoint(rng),
                                    latticePoint(rng), latticePoint(rng));
  EXPECT_GT(hits, 300);
}

TEST(SegmentTriangle, PiercingHitPointAndBarycentrics) {
  const Vector3d a(0, 0, 0), b(4, 0, 0), c(0, 4, 0);
  const auto hit = intersectSegmentTriangle(Vector3d(1, 2, 3), Vector3d(1, 2, -1), a, b, c);
  ASSERT_TRUE(hit);
  EXPECT_DOUBLE_EQ(hit->t, 0.75);
  EXPECT_TRUE(hit->point.isApprox(Vector3d(1, 2, 0)));
  EXPECT_TRUE(hit->barycentric.isApprox(Vector3d(0.25, 0.25, 0.5)));
}

TEST(SegmentTriangle, NamedDegenerateCases) {
  const Vector3d a(0, 0, 0), b(4, 0, 0), c(0, 4, 0);
  // touching a corner from above
  EXPECT_TRUE(intersectSegmentTriangle(Vector3d(0, 0, 1), Vector3d(0, 0, 0), a, b, c));
  // parallel to the plane, above it
  EXPECT_FALSE(intersectSegmentTriangle(Vector3d(1, 1, 1), Vector3d(2, 1, 1), a, b, c));
  // coplanar, entering from outside: the first point inside is the entry on edge x = 0
  const auto entry = intersectSegmentTriangle(Vector3d(-2, 1, 0), Vector3d(2, 1, 0), a, b, c);
  ASSERT_TRUE(entry);
  EXPECT_NEAR(entry->t, 0.5, 1e-12);
  EXPECT_LT((entry->point - Vector3d(0, 1, 0)).norm(), 1e-12);
  // coplanar, starting inside
  const auto inside = intersectSegmentTriangle(Vector3d(1, 1, 0), Vector3d(9, 9, 0), a, b, c);
  ASSERT_TRUE(inside);
  EXPECT_DOUBLE_EQ(inside->t, 0.0);
  // coplanar, missing
  EXPECT_FALSE(intersectSegmentTriangle(Vector3d(3, 3, 0), Vector3d(9, 3, 0), a, b, c));
  // zero-area triangle (a segment along x) pierced from above, and missed
  EXPECT_TRUE(intersectSegmentTriangle(Vector3d(1, 0, 1), Vector3d(1, 0, -1), a, b, Vector3d(2, 0, 0)));
  EXPECT_FALSE(intersectSegmentTriangle(Vector3d(1, 1, 1), Vector3d(1, 1, -1), a, b, Vector3d(2, 0, 0)));
  // zero-length segment on the face, and off it
  EXPECT_TRUE(intersectSegmentTriangle(Vector3d(1, 1, 0), Vector3d(1, 1, 0), a, b, c));
  EXPECT_FALSE(intersectSegmentTriangle(Vector3d(1, 1, 0.5), Vector3d(1, 1, 0.5), a, b, c));
}

}  // namespace
}  // namespace microsim::sim::collide
