#pragma once
// Brute-force references for the collision tests: the distance between the convex hulls of
// two small point sets by enumerating every pair of sub-simplices, and all-pairs by trying
// every pair of features.

#include <Eigen/Dense>

#include <algorithm>
#include <limits>
#include <random>
#include <vector>

namespace microsim::sim::collide::brute {

using Eigen::Vector3d;

/// Distance between conv(A) and conv(B) for 1–3 points each. For every non-empty subset pair
/// the least-squares closest points of the two affine hulls are computed (minimum-norm
/// solution); those with non-negative weights are candidates, and the least candidate is the
/// distance (the optimum lies in the relative interior of some face pair).
inline double hullDistance(const std::vector<Vector3d>& a, const std::vector<Vector3d>& b) {
  double best = std::numeric_limits<double>::infinity();
  const int na = static_cast<int>(a.size());
  const int nb = static_cast<int>(b.size());
  for (int ma = 1; ma < (1 << na); ++ma)
    for (int mb = 1; mb < (1 << nb); ++mb) {
      std::vector<Vector3d> sa, sb;
      for (int i = 0; i < na; ++i)
        if (ma & (1 << i)) sa.push_back(a[i]);
      for (int j = 0; j < nb; ++j)
        if (mb & (1 << j)) sb.push_back(b[j]);
      const int ka = static_cast<int>(sa.size()) - 1;
      const int kb = static_cast<int>(sb.size()) - 1;
      const Vector3d r0 = sa[0] - sb[0];
      if (ka + kb == 0) {
        best = std::min(best, r0.norm());
        continue;
      }

      // minimise |r0 + Σ α_i (sa_i − sa_0) − Σ β_j (sb_j − sb_0)|
      Eigen::MatrixXd m(3, ka + kb);
      for (int i = 0; i < ka; ++i) m.col(i) = sa[i + 1] - sa[0];
      for (int j = 0; j < kb; ++j) m.col(ka + j) = -(sb[j + 1] - sb[0]);
      const Eigen::VectorXd w = m.completeOrthogonalDecomposition().solve(-r0);
      const double tol = 1e-12;
      double sumA = 0.0, sumB = 0.0;
      bool feasible = true;
      for (int i = 0; i < ka; ++i) {
        feasible = feasible && w[i] >= -tol;
        sumA += w[i];
      }
      for (int j = 0; j < kb; ++j) {
        feasible = feasible && w[ka + j] >= -tol;
        sumB += w[ka + j];
      }
      if (!feasible || sumA > 1.0 + tol || sumB > 1.0 + tol) continue;
      best = std::min(best, (r0 + m * w).norm());
    }
  return best;
}

/// Random points with coordinates in {−2, −1, 0, 1, 2}: exact arithmetic, so coplanar,
/// parallel, touching and zero-area configurations come up often and are decided exactly.
inline Vector3d latticePoint(std::mt19937& rng) {
  std::uniform_int_distribution<int> pick(-2, 2);
  return Vector3d(pick(rng), pick(rng), pick(rng));
}

/// Random points in the cube [−1, 1]³ (general position).
inline Vector3d cubePoint(std::mt19937& rng) {
  std::uniform_real_distribution<double> pick(-1.0, 1.0);
  return Vector3d(pick(rng), pick(rng), pick(rng));
}

}  // namespace microsim::sim::collide::brute
