#include "tracking/frame_assembler.h"

#include <algorithm>

namespace microsim::tracking {

std::optional<sim::Hand> DeviceMapping::handForDevice(const std::string& device) const {
  for (int h = 0; h < sim::kHandCount; ++h)
    if (!hands[h].device.empty() && hands[h].device == device) return static_cast<sim::Hand>(h);
  return std::nullopt;
}

std::optional<sim::Hand> DeviceMapping::handForChannel(const std::string& channel) const {
  for (int h = 0; h < sim::kHandCount; ++h)
    if (!hands[h].closureChannel.empty() && hands[h].closureChannel == channel) return static_cast<sim::Hand>(h);
  return std::nullopt;
}

double closureFromChannel(const HandMapping& hand, double value) {
  const double span = hand.closureClosed - hand.closureOpen;
  if (span == 0.0) return 0.0;
  return std::clamp((value - hand.closureOpen) / span, 0.0, 1.0);
}

FrameAssembler::FrameAssembler(DeviceMapping mapping) : mapping_(std::move(mapping)) {
  for (int h = 0; h < sim::kHandCount; ++h) frame_.hands[h].instrument = mapping_.hands[h].instrument;
}

std::optional<sim::InputFrame> FrameAssembler::applyPose(const RawPose& pose, double frameTime) {
  const std::optional<sim::Hand> hand = mapping_.handForDevice(pose.device);
  if (!hand) return std::nullopt;
  sim::HandInput& in = frame_.hand(*hand);
  in.tracked = true;
  in.position = pose.matrix.block<3, 1>(0, 3);
  // a position-only device keeps the orientation it last had
  if (pose.hasRotation) {
    in.orientation = Eigen::Quaterniond(Eigen::Matrix3d(pose.matrix.block<3, 3>(0, 0)));
    in.orientation.normalize();
  }
  frame_.time = frameTime;
  return frame_;
}

std::optional<sim::InputFrame> FrameAssembler::applyChannel(const ChannelValue& value, double frameTime) {
  const std::optional<sim::Hand> hand = mapping_.handForChannel(value.channel);
  if (!hand) return std::nullopt;
  frame_.hand(*hand).closure = closureFromChannel(mapping_.hands[static_cast<int>(*hand)], value.value);
  frame_.time = frameTime;
  return frame_;
}

sim::InputFrame FrameAssembler::lose(double frameTime) {
  for (sim::HandInput& in : frame_.hands) in.tracked = false;
  frame_.time = frameTime;
  return frame_;
}

}  // namespace microsim::tracking
