#pragma once
// Test geometry for the collision benchmark and tests: a latitude–longitude ball as plain
// positions (3 by #V, mm) and a triangle list (the flat grids come from sim/mesh/grid.h).

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace microsim::bench {

struct TriangleSoup {
  Eigen::Matrix3Xd x;                         ///< 3 by #V, mm
  std::vector<std::array<int, 3>> triangles;  ///< vertex indices
};

/// A ball of `radius` mm about `centre`: `slices` meridians and `bands` latitude bands, with
/// one vertex at each pole; 2 slices (bands − 1) triangles (32 × 17 gives 1024).
inline TriangleSoup uvBall(int slices, int bands, double radius,
                           const Eigen::Vector3d& centre = Eigen::Vector3d::Zero()) {
  TriangleSoup soup;
  const int rings = bands - 1;
  soup.x.resize(3, 2 + static_cast<Eigen::Index>(rings) * slices);
  soup.x.col(0) = centre + Eigen::Vector3d(0, 0, -radius);
  soup.x.col(1) = centre + Eigen::Vector3d(0, 0, radius);
  for (int r = 0; r < rings; ++r) {
    const double polar = std::numbers::pi * (r + 1) / bands;
    for (int s = 0; s < slices; ++s) {
      const double azimuth = 2.0 * std::numbers::pi * s / slices;
      soup.x.col(2 + r * slices + s) =
          centre + radius * Eigen::Vector3d(std::sin(polar) * std::cos(azimuth),
                                            std::sin(polar) * std::sin(azimuth),
                                            -std::cos(polar));
    }
  }
  const auto ring = [&](int r, int s) { return 2 + r * slices + (s % slices); };
  for (int s = 0; s < slices; ++s) {
    soup.triangles.push_back({0, ring(0, s + 1), ring(0, s)});
    soup.triangles.push_back({1, ring(rings - 1, s), ring(rings - 1, s + 1)});
  }
  for (int r = 0; r + 1 < rings; ++r)
    for (int s = 0; s < slices; ++s) {
      soup.triangles.push_back({ring(r, s), ring(r, s + 1), ring(r + 1, s + 1)});
      soup.triangles.push_back({ring(r, s), ring(r + 1, s + 1), ring(r + 1, s)});
    }
  return soup;
}

/// The paper's deformation (§5.4): every vertex within `radius` (mm) of vertex `centre`
/// moves along z by height·unit / (unit + d), d its distance to the centre, i.e. inversely
/// with distance; unit = 1 mm. Returns the moved vertices in index order.
inline std::vector<int> bump(Eigen::Matrix3Xd& x, int centre, double radius, double height) {
  const Eigen::Vector3d c = x.col(centre);
  std::vector<int> moved;
  for (int v = 0; v < x.cols(); ++v) {
    const double d = (x.col(v) - c).norm();
    if (d > radius) continue;
    x(2, v) += height / (1.0 + d);
    moved.push_back(v);
  }
  return moved;
}

}  // namespace microsim::bench
