#include "tracking/rate_control.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace microsim::tracking {

sim::HandInput applyRate(const sim::HandInput& hand, const RateCommand& command, const ViewAxes& view,
                         const RateLimits& limits, double dtS) {
  sim::HandInput out = hand;
  const Eigen::Vector3d t = command.translation.cwiseMax(-1.0).cwiseMin(1.0);
  const Eigen::Vector3d r = command.rotation.cwiseMax(-1.0).cwiseMin(1.0);

  // translation along the view's axes
  out.position += limits.mmPerS * dtS * (t.x() * view.right + t.y() * view.up + t.z() * view.toward);

  // rotation about the tip, about the view-frame axis of the deflection
  const Eigen::Vector3d axis = r.x() * view.right + r.y() * view.up + r.z() * view.toward;
  const double magnitude = axis.norm();
  if (magnitude > 0.0) {
    const double angle = magnitude * limits.degPerS * std::numbers::pi / 180.0 * dtS;
    out.orientation = (Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis / magnitude)) * hand.orientation).normalized();
  }
  return out;
}

double pastDeadZone(double value, double dead) {
  const double magnitude = std::min(std::abs(value), 1.0);
  if (magnitude <= dead || dead >= 1.0) return 0.0;
  return std::copysign((magnitude - dead) / (1.0 - dead), value);
}

std::optional<sim::InputFrame> toolsShown(const sim::RenderSnapshot& snapshot) {
  sim::InputFrame frame;
  frame.time = snapshot.time;
  bool any = false;
  for (int h = 0; h < sim::kHandCount; ++h) {
    const sim::ToolSnapshot& tool = snapshot.forceps[static_cast<std::size_t>(h)];
    sim::HandInput& in = frame.hands[static_cast<std::size_t>(h)];
    if (!tool.present) continue;
    const Eigen::Matrix4d pose = tool.pose.cast<double>();
    in.instrument = snapshot.instruments[static_cast<std::size_t>(h)];
    in.tracked = true;
    in.position = pose.block<3, 1>(0, 3);
    // the snapshot's matrix is single precision: the quaternion is renormalised
    in.orientation = Eigen::Quaterniond(Eigen::Matrix3d(pose.block<3, 3>(0, 0))).normalized();
    const sim::ScissorsSnapshot& scissors = snapshot.scissors[static_cast<std::size_t>(h)];
    in.closure = std::clamp(scissors.present ? scissors.closure : tool.closure, 0.0, 1.0);
    any = true;
  }
  if (!any) return std::nullopt;
  return frame;
}

}  // namespace microsim::tracking
