#pragma once
// The one tolerance of the exact tests: a point within 1e-12 of the coordinates' scale of a
// plane counts as on it, and segments that close count as meeting. Below it, rounding
// decides, and tests that must agree both ways round (A against B, B against A) would not.

#include <Eigen/Core>

#include <algorithm>
#include <initializer_list>

namespace microsim::sim::collide {

inline constexpr double kRelativeTolerance = 1e-12;

/// Largest absolute coordinate of the points (mm), at least the smallest normal double.
inline double coordinateScale(std::initializer_list<const Eigen::Vector3d*> points) {
  double scale = 1e-300;
  for (const Eigen::Vector3d* p : points) scale = std::max(scale, p->cwiseAbs().maxCoeff());
  return scale;
}

}  // namespace microsim::sim::collide
