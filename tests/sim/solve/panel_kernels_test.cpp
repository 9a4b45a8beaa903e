// The supernodal factorisation's dense kernels against plain loops: the products of 3-row slices
// in the order the header states (to the bit), the pivot blocks against Eigen's Cholesky.
#include "solve/panel_kernels.h"

#include <Eigen/Cholesky>

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace microsim::sim::detail::panel {
namespace {

std::vector<double> randomNumbers(std::size_t count, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::vector<double> v(count);
  for (double& x : v) x = value(random);
  return v;
}

/// Σ_{k<n} p[k] q[k] as the kernels sum it: even k, odd k, then the two.
double laneOrderDot(const double* p, const double* q, int n) {
  double even = 0.0, odd = 0.0;
  for (int k = 0; k < n; k += 2) even += p[k] * q[k];
  for (int k = 1; k < n; k += 2) odd += p[k] * q[k];
  return even + odd;
}

TEST(PanelKernels, SubtractProductSumsInTheStatedOrder) {
  const int ld = 23, ldd = 7;
  const std::vector<double> p = randomNumbers(3 * ld, 1), q = randomNumbers(3 * ld, 2);
  for (int n : {0, 1, 2, 5, 12, 23}) {
    std::vector<double> dst = randomNumbers(3 * ldd, 3), expected = dst;
    subtractProduct(p.data(), q.data(), ld, n, dst.data(), ldd);
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        expected[a * ldd + b] -= laneOrderDot(p.data() + a * ld, q.data() + b * ld, n);
        EXPECT_EQ(dst[a * ldd + b], expected[a * ldd + b])
            << "n " << n << " (" << a << ", " << b << ")";
      }
    // the rest of dst's rows untouched
    for (int a = 0; a < 3; ++a)
      for (int c = 3; c < ldd; ++c) EXPECT_EQ(dst[a * ldd + c], expected[a * ldd + c]);
  }
}

TEST(PanelKernels, SliceTimesVectorAndTransposed) {
  const int ld = 17;
  const std::vector<double> p = randomNumbers(3 * ld, 4), v = randomNumbers(ld, 5);
  for (int n : {0, 3, 6, 17}) {
    std::vector<double> y = randomNumbers(3, 6), expected = y;
    subtractSliceTimes(p.data(), ld, v.data(), n, y.data());
    for (int a = 0; a < 3; ++a) {
      expected[a] -= laneOrderDot(p.data() + a * ld, v.data(), n);
      EXPECT_EQ(y[a], expected[a]);
    }
    std::vector<double> t = randomNumbers(ld, 7), before = t;
    addSliceTransposedTimes(p.data(), ld, v.data(), n, t.data());
    for (int k = 0; k < ld; ++k) {
      const double add = k < n ? (p[k] * v[0] + p[ld + k] * v[1]) + p[2 * ld + k] * v[2] : 0.0;
      EXPECT_EQ(t[k], before[k] + add);
    }
  }
}

TEST(PanelKernels, PivotBlocksAsEigensCholesky) {
  const int ld = 5;
  Eigen::Matrix3d m;
  m << 4.0, 1.0, -0.5, 1.0, 3.0, 0.25, -0.5, 0.25, 2.0;
  std::vector<double> x(3 * ld, 0.0);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) x[r * ld + c] = m(r, c);
  double inverse[3];
  ASSERT_TRUE(factorPivot(x.data(), ld, inverse));
  const Eigen::Matrix3d l = m.llt().matrixL();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c <= r; ++c) EXPECT_NEAR(x[r * ld + c], l(r, c), 1e-15);
    EXPECT_NEAR(inverse[r], 1.0 / l(r, r), 1e-15);
  }
  // y L⁻ᵀ, L⁻¹ v and L⁻ᵀ (v − t)
  std::vector<double> y = randomNumbers(3 * ld, 8);
  const std::vector<double> y0 = y;
  solveAgainstPivot(x.data(), inverse, y.data(), ld);
  for (int r = 0; r < 3; ++r) {
    const Eigen::Vector3d row(y[r * ld], y[r * ld + 1], y[r * ld + 2]);
    const Eigen::Vector3d back = l * row;  // (y L⁻ᵀ) Lᵀ = y, row by row
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(back[c], y0[r * ld + c], 1e-14);
  }
  double v[3] = {0.3, -1.0, 2.0};
  forwardPivot(x.data(), ld, inverse, v);
  EXPECT_LT((l * Eigen::Vector3d(v[0], v[1], v[2]) - Eigen::Vector3d(0.3, -1.0, 2.0)).norm(),
            1e-14);
  const double t[3] = {0.5, 0.25, -0.125};
  double w[3] = {0.3, -1.0, 2.0};
  backwardPivot(x.data(), ld, inverse, t, w);
  EXPECT_LT(
      (l.transpose() * Eigen::Vector3d(w[0], w[1], w[2]) - Eigen::Vector3d(-0.2, -1.25, 2.125))
          .norm(),
      1e-14);
}

TEST(PanelKernels, RefusesAPivotThatIsNotPositiveDefinite) {
  double x[9] = {1.0, 0.0, 0.0, 2.0, 1.0, 0.0, 0.0, 0.0, 1.0};  // lower triangle of [1 2; 2 1]
  double inverse[3];
  EXPECT_FALSE(factorPivot(x, 3, inverse));
  double negative[9] = {-1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0};
  EXPECT_FALSE(factorPivot(negative, 3, inverse));
}

}  // namespace
}  // namespace microsim::sim::detail::panel
