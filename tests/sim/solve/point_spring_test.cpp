// The soft point terms (mesh/point_spring.h) alone: force = −∂E/∂x and Hessian = −∂F/∂x by
// central differences, for two-sided and one-sided terms on weighted points of 1–4 nodes.
#include "microsim/sim/mesh/point_spring.h"
#include "microsim/sim/mesh/spring_model.h"

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <random>

namespace microsim::sim {
namespace {

using PointSpringMatrix = Eigen::Matrix3d;

/// Five nodes at fixed pseudo-random positions in the unit box (mm).
Points pointSpringNodes() {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Points x(3, 5);
  for (Eigen::Index i = 0; i < x.size(); ++i) x.data()[i] = u(rng);
  return x;
}

/// A term on nodes 0..count−1 (count 1..4) with weights of both signs.
PointSpring pointSpringOn(int count, double k) {
  constexpr std::array<double, 4> kWeights{1.0, -0.3, -0.5, 0.8};
  PointSpring s;
  for (int j = 0; j < count; ++j) {
    s.nodes[static_cast<std::size_t>(j)] = j;
    s.weights[static_cast<std::size_t>(j)] = kWeights[static_cast<std::size_t>(j)];
  }
  s.k = k;
  return s;
}

/// Makes `s` one-sided along `normal` with gap `gap` and places its anchor so that
/// n·d − gap = depth at positions x (negative: pressed), with a tangential part too.
void pointSpringMakeOneSided(PointSpring& s, const Points& x, const Vec3& normal, double gap,
                             double depth) {
  s.normal = normal.normalized();
  s.gap = gap;
  s.anchor.setZero();
  const Vec3 g = pointSpringOffset(s, x);
  const Vec3 tangent = s.normal.unitOrthogonal();
  // d = g − anchor = (gap + depth) n + 0.4 t
  s.anchor = g - (gap + depth) * s.normal - 0.4 * tangent;
}

double pointSpringEnergyAt(const PointSpring& s, const Points& x) {
  return pointSpringEnergy(s, pointSpringOffset(s, x));
}

/// The force on every node of the term (3 by 5, µN).
Points pointSpringNodeForces(const PointSpring& s, const Points& x) {
  Points f = Points::Zero(3, x.cols());
  const Vec3 fg = pointSpringForce(s, pointSpringOffset(s, x));
  for (int j = 0; j < s.size(); ++j)
    f.col(s.nodes[static_cast<std::size_t>(j)]) += s.weights[static_cast<std::size_t>(j)] * fg;
  return f;
}

/// Checks node forces against −∂E/∂x and the node Hessian blocks c_a c_b H against −∂F_a/∂x_b.
void pointSpringCheckDerivatives(const PointSpring& s, const Points& x) {
  const double h = 1e-6;
  const Points f = pointSpringNodeForces(s, x);
  const PointSpringMatrix hg = pointSpringHessian(s, pointSpringOffset(s, x));
  for (int b = 0; b < static_cast<int>(x.cols()); ++b) {
    PointSpringMatrix dFa[5];
    for (int d = 0; d < 3; ++d) {
      Points plus = x, minus = x;
      plus(d, b) += h;
      minus(d, b) -= h;
      const double dE = (pointSpringEnergyAt(s, plus) - pointSpringEnergyAt(s, minus)) / (2 * h);
      EXPECT_NEAR(f(d, b), -dE, 1e-6 * (1.0 + f.norm())) << "node " << b << " axis " << d;
      const Points df = (pointSpringNodeForces(s, plus) - pointSpringNodeForces(s, minus)) / (2 * h);
      for (int a = 0; a < 5; ++a) dFa[a].col(d) = -df.col(a);
    }
    for (int a = 0; a < 5; ++a) {
      // nodes past the term's size have weight 0: their blocks vanish
      const double ca = a < s.size() ? s.weights[static_cast<std::size_t>(a)] : 0.0;
      const double cb = b < s.size() ? s.weights[static_cast<std::size_t>(b)] : 0.0;
      const PointSpringMatrix expected = ca * cb * hg;
      EXPECT_LT((expected - dFa[a]).norm(), 1e-5 * (1.0 + hg.norm()))
          << "Hessian block (" << a << ", " << b << ")";
    }
  }
}

TEST(PointSpring, SizeCountsNodesUpToTheFirstUnused) {
  PointSpring s;
  EXPECT_EQ(s.size(), 0);
  s.nodes = {4, 2, -1, 3};
  EXPECT_EQ(s.size(), 2);
  s.nodes = {4, 2, 1, 3};
  EXPECT_EQ(s.size(), 4);
  EXPECT_FALSE(s.oneSided());
  s.normal = Vec3::UnitY();
  EXPECT_TRUE(s.oneSided());
}

TEST(PointSpring, OffsetIsTheWeightedPointMinusTheAnchor) {
  const Points x = pointSpringNodes();
  PointSpring s = pointSpringOn(3, 5.0);
  s.anchor = Vec3(0.1, -0.2, 0.3);
  const Vec3 expected = 1.0 * x.col(0) - 0.3 * x.col(1) - 0.5 * x.col(2) - s.anchor;
  EXPECT_LT((pointSpringOffset(s, x) - expected).norm(), 1e-15);
}

TEST(PointSpring, TwoSidedForceAndHessianMatchFiniteDifferences) {
  const Points x = pointSpringNodes();
  for (int count = 1; count <= 4; ++count) {
    SCOPED_TRACE(count);
    PointSpring s = pointSpringOn(count, 7.0);
    s.anchor = Vec3(0.3, -0.1, 0.2);
    const Vec3 d = pointSpringOffset(s, x);
    EXPECT_LT((pointSpringForce(s, d) + 7.0 * d).norm(), 1e-12);
    EXPECT_NEAR(pointSpringEnergy(s, d), 3.5 * d.squaredNorm(), 1e-12);
    EXPECT_LT((pointSpringHessian(s, d) - 7.0 * PointSpringMatrix::Identity()).norm(), 1e-12);
    pointSpringCheckDerivatives(s, x);
  }
}

TEST(PointSpring, PressedOneSidedForceAndHessianMatchFiniteDifferences) {
  const Points x = pointSpringNodes();
  const Vec3 normal = Vec3(1.0, 2.0, -0.5).normalized();
  for (int count = 1; count <= 4; ++count) {
    SCOPED_TRACE(count);
    PointSpring s = pointSpringOn(count, 11.0);
    pointSpringMakeOneSided(s, x, normal, 0.05, -0.2);
    const Vec3 d = pointSpringOffset(s, x);
    EXPECT_NEAR(normal.dot(d) - 0.05, -0.2, 1e-12);
    // pushes along n by k times the depth, whatever the tangential offset
    EXPECT_LT((pointSpringForce(s, d) - 11.0 * 0.2 * normal).norm(), 1e-12);
    EXPECT_NEAR(pointSpringEnergy(s, d), 0.5 * 11.0 * 0.2 * 0.2, 1e-12);
    EXPECT_LT((pointSpringHessian(s, d) - 11.0 * normal * normal.transpose()).norm(), 1e-12);
    pointSpringCheckDerivatives(s, x);
  }
}

TEST(PointSpring, OneSidedNotPressedIsInertAndMatchesFiniteDifferences) {
  const Points x = pointSpringNodes();
  const Vec3 normal = Vec3(-0.3, 0.1, 1.0).normalized();
  for (int count = 1; count <= 4; ++count) {
    SCOPED_TRACE(count);
    PointSpring s = pointSpringOn(count, 11.0);
    pointSpringMakeOneSided(s, x, normal, 0.05, 0.2);
    const Vec3 d = pointSpringOffset(s, x);
    EXPECT_TRUE(pointSpringForce(s, d).isZero(0.0));
    EXPECT_EQ(pointSpringEnergy(s, d), 0.0);
    EXPECT_TRUE(pointSpringHessian(s, d).isZero(0.0));
    pointSpringCheckDerivatives(s, x);
  }
}

TEST(PointSpring, OneSidedIsZeroFromTheGapOnAndPushesJustInside) {
  PointSpring s;
  s.nodes[0] = 0;
  s.weights[0] = 1.0;
  s.normal = Vec3::UnitZ();
  s.gap = 0.1;
  s.k = 4.0;
  for (double z : {0.1, 0.1 + 1e-12, 0.5, 100.0}) {
    const Vec3 d(0.7, -0.2, z);
    EXPECT_TRUE(pointSpringForce(s, d).isZero(0.0)) << "n·d = " << z;
    EXPECT_EQ(pointSpringEnergy(s, d), 0.0) << "n·d = " << z;
    EXPECT_TRUE(pointSpringHessian(s, d).isZero(0.0)) << "n·d = " << z;
  }
  // just inside, and far behind the surface: still along +n, k times the depth
  for (double z : {0.1 - 1e-9, 0.0, -3.0}) {
    const Vec3 f = pointSpringForce(s, Vec3(0.7, -0.2, z));
    EXPECT_NEAR(f.z(), 4.0 * (0.1 - z), 1e-12) << "n·d = " << z;
    EXPECT_EQ(f.x(), 0.0);
    EXPECT_EQ(f.y(), 0.0);
    EXPECT_GT(f.z(), 0.0);
  }
}

TEST(PointSpring, NodeForcesOfANodeAgainstAFaceSumToZero) {
  // weights (1, −u, −v, −w) with u + v + w = 1: the term pushes node and face apart and
  // adds no net force to the tissue
  const Points x = pointSpringNodes();
  PointSpring s;
  s.nodes = {0, 1, 2, 3};
  s.weights = {1.0, -0.2, -0.5, -0.3};
  s.normal = Vec3::UnitX();
  s.gap = 2.0;
  s.k = 3.0;
  const Points f = pointSpringNodeForces(s, x);
  ASSERT_GT(f.col(0).norm(), 0.0);
  EXPECT_LT(f.rowwise().sum().norm(), 1e-12);
}

}  // namespace
}  // namespace microsim::sim
