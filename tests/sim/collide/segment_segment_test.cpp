#include "microsim/sim/collide/segment_segment.h"

#include "sim/collide/brute_force.h"

#include <gtest/gtest.h>

namespace microsim::sim::collide {
namespace {

using brute::cubePoint;
using Eigen::Vector3d;
using brute::hullDistance;
using brute::latticePoint;

void expectSegmentSegmentMatchesBruteForce(const Vector3d& p0, const Vector3d& p1, const Vector3d& q0,
                             const Vector3d& q1) {
  const SegmentClosest got = closestSegmentSegment(p0, p1, q0, q1);
  const double want = hullDistance({p0, p1}, {q0, q1});
  ASSERT_NEAR(got.distance, want, 1e-9) << p0.transpose() << " | " << p1.transpose() << " | "
                                        << q0.transpose() << " | " << q1.transpose();
  EXPECT_GE(got.s, 0.0);
  EXPECT_LE(got.s, 1.0);
  EXPECT_GE(got.t, 0.0);
  EXPECT_LE(got.t, 1.0);
  EXPECT_LT((p0 + got.s * (p1 - p0) - got.onFirst).norm(), 1e-12);
  EXPECT_LT((q0 + got.t * (q1 - q0) - got.onSecond).norm(), 1e-12);
  EXPECT_NEAR((got.onFirst - got.onSecond).norm(), got.distance, 1e-12);
}

TEST(SegmentSegment, RandomCasesMatchBruteForce) {
  std::mt19937 rng(11);
  for (int i = 0; i < 4000; ++i)
    expectSegmentSegmentMatchesBruteForce(cubePoint(rng), cubePoint(rng), cubePoint(rng), cubePoint(rng));
}

TEST(SegmentSegment, LatticeCasesMatchBruteForce) {
  // parallel, collinear, crossing, touching and zero-length segments
  std::mt19937 rng(12);
  for (int i = 0; i < 4000; ++i)
    expectSegmentSegmentMatchesBruteForce(latticePoint(rng), latticePoint(rng), latticePoint(rng),
                            latticePoint(rng));
}

TEST(SegmentSegment, NamedDegenerateCases) {
  const Vector3d o(0, 0, 0), x(1, 0, 0);
  // parallel, offset by 1 in y, overlapping in x
  EXPECT_DOUBLE_EQ(closestSegmentSegment(o, x, Vector3d(0.5, 1, 0), Vector3d(1.5, 1, 0)).distance, 1.0);
  // collinear, disjoint: gap of 1
  EXPECT_DOUBLE_EQ(closestSegmentSegment(o, x, Vector3d(2, 0, 0), Vector3d(3, 0, 0)).distance, 1.0);
  // crossing at right angles
  EXPECT_NEAR(closestSegmentSegment(o, x, Vector3d(0.5, -1, 0), Vector3d(0.5, 1, 0)).distance, 0.0, 1e-15);
  // skew, crossing over at height 1
  const SegmentClosest skew = closestSegmentSegment(o, x, Vector3d(0.5, -1, 1), Vector3d(0.5, 1, 1));
  EXPECT_DOUBLE_EQ(skew.distance, 1.0);
  EXPECT_DOUBLE_EQ(skew.s, 0.5);
  EXPECT_DOUBLE_EQ(skew.t, 0.5);
  // two points
  EXPECT_DOUBLE_EQ(closestSegmentSegment(o, o, x, x).distance, 1.0);
}

}  // namespace
}  // namespace microsim::sim::collide
