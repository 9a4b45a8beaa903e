#pragma once
// Where 0° lies round a vessel (DESIGN.md §Assessment): the direction toward the microscope,
// the camera eye seen from the cut centre with its part along the axis removed. Pierce
// angles, the leak test's suture line and a stay stitch's angle all turn from it,
// right-handed about end 0's axis. One definition, so the three agree. CircumferenceFrame
// turns both ways between an angle and a direction, for the checks that walk the suture line
// (scene/leak_test.h, scene/end_state_check.h).
//
// Units: millimetres, degrees.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

namespace microsim::sim {

/// The unit vector ⟂ `axis` (unit) nearest `toward`; when `toward` lies along the axis (the
/// microscope looks straight down it), any unit vector ⟂ `axis`.
inline Eigen::Vector3d circumferenceZero(const Eigen::Vector3d& axis,
                                         const Eigen::Vector3d& toward) {
  const Eigen::Vector3d p = toward - toward.dot(axis) * axis;
  return p.norm() > 1e-12 ? Eigen::Vector3d(p.normalized())
                          : Eigen::Vector3d(axis.unitOrthogonal());
}

/// The angles about one axis: 0° along `zero`, right-handed about `axis` (both unit, ⟂).
struct CircumferenceFrame {
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();
  Eigen::Vector3d zero = Eigen::Vector3d::UnitZ();

  /// The unit direction ⟂ axis at `deg`.
  Eigen::Vector3d direction(double deg) const {
    const double a = deg * std::numbers::pi / 180.0;
    return std::cos(a) * zero + std::sin(a) * axis.cross(zero);
  }
  /// The angle of `offset` (a point minus a point of the axis line), degrees in [0, 360).
  double angleDeg(const Eigen::Vector3d& offset) const {
    double deg =
        std::atan2(offset.dot(axis.cross(zero)), offset.dot(zero)) * 180.0 / std::numbers::pi;
    if (deg < 0.0) deg += 360.0;
    return deg >= 360.0 ? 0.0 : deg;
  }
};

/// The frame about unit `axis` whose 0° is the direction ⟂ axis nearest `toward`.
inline CircumferenceFrame circumferenceFrame(const Eigen::Vector3d& axis,
                                             const Eigen::Vector3d& toward) {
  return {axis, circumferenceZero(axis, toward)};
}

}  // namespace microsim::sim
