#pragma once
// What a tracker source reports before it becomes an InputFrame: per-device raw poses in
// the tracker's own frame, named scalar channels (forceps closure), and the reasons a
// message or pose was refused. A source counts every refusal by reason; a refused
// message never reaches the simulation and never ends the link.

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <string>

namespace microsim::tracking {

/// One pose of one tracked device, as the tracker reported it.
struct RawPose {
  std::string device;  ///< OpenIGTLink device name (TDATA: the element's instrument name)
  double time = 0.0;   ///< s, the source's clock (message timestamp; receive time when it has none)
  /// tool frame → tracker frame, homogeneous 4 by 4; rotation block orthonormal, translation in mm
  Eigen::Matrix4d matrix = Eigen::Matrix4d::Identity();
  bool hasRotation = true;  ///< false: a position-only message (POSITION without quaternion)

  bool operator==(const RawPose&) const = default;
};

/// One value of a named scalar channel (OpenIGTLink SENSOR, first element).
struct ChannelValue {
  std::string channel;
  double time = 0.0;   ///< s, source clock as for RawPose
  double value = 0.0;  ///< in the channel's own unit (e.g. the forceps' raw grip reading)

  bool operator==(const ChannelValue&) const = default;
};

/// Why a message or a pose was refused. The values index RejectionCounts: append only.
enum class Rejection : std::uint8_t {
  BadHeader = 0,       ///< not an OpenIGTLink header (bad version, non-ASCII type, absurd size): resync
  BadCrc,              ///< the body's CRC-64 does not match the header's
  WrongBodySize,       ///< the body size does not fit the message type (TRANSFORM ≠ 48 bytes, ...)
  UnknownType,         ///< a well-formed message of a type this source does not read
  Truncated,           ///< the stream ended inside a message
  NonFinite,           ///< NaN or Inf in a matrix, position, quaternion or channel value
  NotOrthonormal,      ///< the rotation block is not orthonormal with determinant +1
  TooFast,             ///< moved faster than the configured speed since the last accepted pose
  TimeBackwards,       ///< timestamp earlier than the device's last accepted one
  InvalidFrame,        ///< the assembled InputFrame failed sim::validateSequence
};
inline constexpr int kRejectionCount = 10;

/// Stable machine key of a reason ("bad_crc", ...), used in JSON; not a user-facing sentence.
const char* rejectionKey(Rejection r);

/// Refusals counted by reason.
struct RejectionCounts {
  std::array<std::uint64_t, kRejectionCount> counts{};

  void add(Rejection r, std::uint64_t n = 1) { counts[static_cast<int>(r)] += n; }
  std::uint64_t operator[](Rejection r) const { return counts[static_cast<int>(r)]; }
  std::uint64_t total() const {
    std::uint64_t t = 0;
    for (std::uint64_t c : counts) t += c;
    return t;
  }
  bool operator==(const RejectionCounts&) const = default;
};

}  // namespace microsim::tracking
