#pragma once
// OpenIGTLink stream decoding, without sockets: bytes in, poses, channel values and
// counted refusals out. The client feeds it whatever the socket delivered; tests feed it
// hand-made byte strings.
//
// Framing. Every message is a 58-byte header (version u16, type char[12], device
// char[20], timestamp u64, body size u64, CRC-64 u64, big-endian) and `body size` bytes.
// Versions 1 and 2 share this layout (PLUS and 3D Slicer send version 1 by default). A
// message is decoded only when its whole body has arrived. Refusals, in the order they
// are checked:
//   header implausible (version not 1 or 2, type or device not printable ASCII, type
//   empty, body larger than maxBodyBytes) → BadHeader once, then the decoder drops one
//   byte at a time until a plausible header starts (resynchronisation), so a corrupt
//   stream costs messages, not the link;
//   CRC-64 of the body ≠ header CRC → BadCrc (the body is skipped, framing kept);
//   type not TRANSFORM, POSITION, TDATA or SENSOR → UnknownType;
//   body size not that of the type → WrongBodySize
//     (TRANSFORM 48; POSITION 12, 24 or 28; TDATA a positive multiple of 70; SENSOR 10 + 8 n, n ≥ 1);
//   stream closed inside a message → Truncated (endOfStream()).
// Numeric checks (finite, orthonormal, speed, time order) belong to PoseFilter.
//
// Decoding. TRANSFORM: 12 float32, the rotation's three columns then the translation
// (column-major 3 by 4). POSITION: position (x, y, z) then quaternion (qx, qy, qz, w);
// 24 bytes carry (qx, qy, qz) and w = sqrt(1 − |q|²); 12 bytes carry no orientation.
// TDATA: elements of 70 bytes (name char[20], type u8, reserved u8, 12 float32 as
// TRANSFORM), one RawPose per element named after the element. SENSOR: larray u8, status
// u8, unit u64, then larray float64; the first value is the channel's value.
// Timestamp: high 32 bits seconds, low 32 bits fraction of 2^32; 0 means "none" and the
// caller's receive time is used.

#include "tracking/tracker_types.h"

#include <cstdint>
#include <span>
#include <vector>

namespace microsim::tracking {

inline constexpr int kIgtlHeaderSize = 58;

/// What a feed produced. `order` keeps the stream order across the three lists, so a
/// consumer can replay poses, channel values and refusals as they arrived.
struct IgtlDecodeOutput {
  enum class Kind : std::uint8_t { Pose, Channel, Rejection };
  struct Item {
    Kind kind;
    std::size_t index;  ///< into poses, channels or rejections
  };

  std::vector<RawPose> poses;
  std::vector<ChannelValue> channels;
  std::vector<Rejection> rejections;
  std::vector<Item> order;

  void add(RawPose p) {
    order.push_back({Kind::Pose, poses.size()});
    poses.push_back(std::move(p));
  }
  void add(ChannelValue v) {
    order.push_back({Kind::Channel, channels.size()});
    channels.push_back(std::move(v));
  }
  void add(Rejection r) {
    order.push_back({Kind::Rejection, rejections.size()});
    rejections.push_back(r);
  }
  void clear() {
    poses.clear();
    channels.clear();
    rejections.clear();
    order.clear();
  }
};

class IgtlDecoder {
 public:
  /// Largest body accepted, bytes; beyond it a header is taken for garbage.
  explicit IgtlDecoder(std::uint64_t maxBodyBytes = 1u << 20) : maxBodyBytes_(maxBodyBytes) {}

  /// Appends bytes and decodes every message now complete. `receiveTime` (s) stamps
  /// messages whose header carries no timestamp.
  void feed(std::span<const std::uint8_t> bytes, double receiveTime, IgtlDecodeOutput& out);

  /// The stream closed: a partial message left in the buffer counts as Truncated. Resets.
  void endOfStream(IgtlDecodeOutput& out);

  /// Bytes waiting for the rest of their message.
  std::size_t buffered() const { return buffer_.size() - start_; }

 private:
  void decodeBody(const std::uint8_t* header, const std::uint8_t* body, std::uint64_t size,
                  double receiveTime, IgtlDecodeOutput& out) const;

  std::uint64_t maxBodyBytes_;
  std::vector<std::uint8_t> buffer_;
  std::size_t start_ = 0;   ///< first unread byte of buffer_
  bool resyncing_ = false;  ///< inside garbage after a BadHeader; not counted again
};

/// Encodes a 58-byte version-1 header for `body` (the CRC is computed). For tests and
/// tools that speak OpenIGTLink without the library's message classes.
std::vector<std::uint8_t> encodeIgtlHeader(const char* type, const std::string& device,
                                           std::uint64_t timestamp, std::span<const std::uint8_t> body,
                                           std::uint16_t version = 1);

/// Seconds as an OpenIGTLink timestamp (high 32 bits seconds, low 32 bits fraction).
std::uint64_t toIgtlTimestamp(double seconds);

}  // namespace microsim::tracking
