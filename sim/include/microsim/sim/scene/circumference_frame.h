#pragma once
// Where 0° lies round a vessel (DESIGN.md §Assessment): the direction toward the microscope,
// the camera eye seen from the cut centre with its part along the axis removed. Pierce
// angles, the leak test's suture line and a stay stitch's angle all turn from it,
// right-handed about end 0's axis. One definition, so the three agree.
//
// Units: millimetres.

#include <Eigen/Core>

namespace microsim::sim {

/// The unit vector ⟂ `axis` (unit) nearest `toward`; when `toward` lies along the axis (the
/// microscope looks straight down it), any unit vector ⟂ `axis`.
inline Eigen::Vector3d circumferenceZero(const Eigen::Vector3d& axis,
                                         const Eigen::Vector3d& toward) {
  const Eigen::Vector3d p = toward - toward.dot(axis) * axis;
  return p.norm() > 1e-12 ? Eigen::Vector3d(p.normalized())
                          : Eigen::Vector3d(axis.unitOrthogonal());
}

}  // namespace microsim::sim
