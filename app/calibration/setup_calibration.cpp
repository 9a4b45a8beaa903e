#include "calibration/setup_calibration.h"

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <cmath>

namespace microsim::calibration {

Eigen::Vector3d scaleMotion(const MotionScaling& scaling, const Eigen::Vector3d& y) {
  return scaling.anchor + (y - scaling.anchor) / scaling.handPerScene;
}

sim::InputFrame toScene(const sim::InputFrame& trackerFrame, const SetupCalibration& calibration) {
  sim::InputFrame out = trackerFrame;
  const Eigen::Matrix3d sq = calibration.trackerToScene.topLeftCorner<3, 3>();
  const Eigen::Vector3d t = calibration.trackerToScene.topRightCorner<3, 1>();
  const double s = std::cbrt(sq.determinant());
  const Eigen::Quaterniond q(Eigen::Matrix3d(sq / s));
  for (int h = 0; h < sim::kHandCount; ++h) {
    sim::HandInput& in = out.hands[h];
    if (!in.tracked) continue;
    const Eigen::Vector3d tip = in.position + in.orientation * calibration.tipOffset[h];
    in.position = scaleMotion(calibration.scaling, sq * tip + t);
    in.orientation = (q * in.orientation).normalized();
  }
  return out;
}

}  // namespace microsim::calibration
