#include "tracking/pose_filter.h"

#include <Eigen/LU>

#include <cmath>
#include <limits>

namespace microsim::tracking {

double orthonormalityError(const Eigen::Matrix4d& m) {
  const Eigen::Matrix3d r = m.block<3, 3>(0, 0);
  if (!(r.determinant() > 0.0)) return std::numeric_limits<double>::infinity();
  return (r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
}

std::optional<Rejection> PoseFilter::check(const RawPose& pose) {
  if (!pose.matrix.allFinite() || !std::isfinite(pose.time)) return Rejection::NonFinite;
  if (!(orthonormalityError(pose.matrix) <= limits_.orthonormalTolerance)) return Rejection::NotOrthonormal;

  // time order and speed against the device's last accepted pose
  auto it = last_.find(pose.device);
  if (it != last_.end()) {
    const RawPose& prev = it->second;
    const double dt = pose.time - prev.time;
    if (dt < 0.0) return Rejection::TimeBackwards;
    const double moved = (pose.matrix.block<3, 1>(0, 3) - prev.matrix.block<3, 1>(0, 3)).norm();
    if (moved > limits_.maxSpeed * dt + limits_.jumpAllowance) return Rejection::TooFast;
    it->second = pose;
  } else {
    last_.emplace(pose.device, pose);
  }
  return std::nullopt;
}

std::optional<Rejection> PoseFilter::check(const ChannelValue& value) {
  if (!std::isfinite(value.value) || !std::isfinite(value.time)) return Rejection::NonFinite;
  auto it = lastChannel_.find(value.channel);
  if (it != lastChannel_.end() && value.time < it->second) return Rejection::TimeBackwards;
  lastChannel_[value.channel] = value.time;
  return std::nullopt;
}

}  // namespace microsim::tracking
