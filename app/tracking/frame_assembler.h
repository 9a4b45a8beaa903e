#pragma once
// From accepted device poses to InputFrames. A DeviceMapping names, per hand, the tracked
// device that carries the tool and the channel that carries the forceps closure; the
// assembler keeps the latest state of both hands and emits a whole frame whenever a
// mapped device or channel moves. Poses stay in the tracker frame (mm): calibration
// (app/calibration) maps them to the scene.
//
// Closure: closure = clamp((v − open) / (closed − open), 0, 1) for a raw channel value v,
// so a grip sensor reading 'open' at rest and 'closed' when squeezed maps to 0..1.

#include "tracking/tracker_types.h"

#include "microsim/sim/scene/input_frame.h"

#include <array>
#include <optional>
#include <string>

namespace microsim::tracking {

struct HandMapping {
  std::string device;          ///< tracked device (TRANSFORM/POSITION device or TDATA element); empty: unused
  sim::Instrument instrument = sim::Instrument::Forceps;
  std::string closureChannel;  ///< SENSOR device giving the closure; empty: closure stays 0
  double closureOpen = 0.0;    ///< channel value when the jaws are open (channel unit)
  double closureClosed = 1.0;  ///< channel value when the jaws are closed (channel unit)
};

struct DeviceMapping {
  std::array<HandMapping, sim::kHandCount> hands{};

  std::optional<sim::Hand> handForDevice(const std::string& device) const;
  std::optional<sim::Hand> handForChannel(const std::string& channel) const;
};

/// Maps a raw closure reading to 0..1 by the hand's range (equation above).
double closureFromChannel(const HandMapping& hand, double value);

class FrameAssembler {
 public:
  explicit FrameAssembler(DeviceMapping mapping = {});

  /// Applies an accepted pose; returns the frame to emit, stamped `frameTime` (s), when the
  /// device belongs to a hand.
  std::optional<sim::InputFrame> applyPose(const RawPose& pose, double frameTime);
  /// Applies an accepted channel value; returns the frame when it is a hand's closure channel.
  std::optional<sim::InputFrame> applyChannel(const ChannelValue& value, double frameTime);
  /// Marks every hand untracked (the link is down); returns the frame to emit.
  sim::InputFrame lose(double frameTime);

  const DeviceMapping& mapping() const { return mapping_; }
  const sim::InputFrame& current() const { return frame_; }

 private:
  DeviceMapping mapping_;
  sim::InputFrame frame_;
};

}  // namespace microsim::tracking
