#include "calibration/pivot_collector.h"

#include <Eigen/Geometry>

#include <cmath>

namespace microsim::calibration {

bool PivotCollector::add(const Eigen::Isometry3d& pose) {
  if (!pose.matrix().allFinite()) return false;
  if (!poses_.empty()) {
    const Eigen::AngleAxisd step(poses_.back().linear().transpose() * pose.linear());
    if (std::abs(step.angle()) * 180.0 / M_PI < options_.minStepDeg) return false;
  }
  poses_.push_back(pose);
  spreadDeg_ = poseSpreadDeg(poses_);
  return true;
}

void PivotCollector::reset() {
  poses_.clear();
  spreadDeg_ = 0.0;
}

}  // namespace microsim::calibration
