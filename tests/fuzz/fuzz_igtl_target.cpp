// Fuzz target for the OpenIGTLink stream decoder: arbitrary bytes from the tracker socket.
#include "fuzz/fuzz_targets.h"

#include "tracking/igtl_decoder.h"

#include <cstring>

namespace microsim::fuzz {

namespace {

// bit-wise, so that a NaN the decoder passes on (PoseFilter refuses it later) compares equal
bool samePoses(const std::vector<tracking::RawPose>& a, const std::vector<tracking::RawPose>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].device != b[i].device || a[i].hasRotation != b[i].hasRotation) return false;
    // NOLINTNEXTLINE(bugprone-suspicious-memory-comparison): bit-wise on purpose (see above)
    if (std::memcmp(&a[i].time, &b[i].time, sizeof(double)) != 0) return false;
    // NOLINTNEXTLINE(bugprone-suspicious-memory-comparison): bit-wise on purpose (see above)
    if (std::memcmp(a[i].matrix.data(), b[i].matrix.data(), sizeof(double) * 16) != 0) return false;
  }
  return true;
}

tracking::IgtlDecodeOutput decodeInReads(const std::uint8_t* data, std::size_t size,
                                         std::size_t readSize) {
  // a small body limit keeps the fuzzer's allocations small while still exercising the
  // "body too large" refusal
  tracking::IgtlDecoder decoder(1u << 16);
  tracking::IgtlDecodeOutput out;
  for (std::size_t at = 0; at < size; at += readSize) {
    const std::size_t n = std::min(readSize, size - at);
    decoder.feed({data + at, n}, 1.0, out);
    if (decoder.buffered() > size) propertyBroken("igtl", "decoder buffers more than it was fed");
  }
  decoder.endOfStream(out);
  if (decoder.buffered() != 0) propertyBroken("igtl", "end of stream left bytes buffered");
  return out;
}

}  // namespace

int fuzzIgtlStream(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  // the first byte picks a read size, as a socket splits a stream arbitrarily; the messages
  // decoded must not depend on it
  const std::size_t readSize = 1 + data[0] % 97;
  const tracking::IgtlDecodeOutput whole = decodeInReads(data + 1, size - 1, size);
  const tracking::IgtlDecodeOutput split = decodeInReads(data + 1, size - 1, readSize);
  if (!samePoses(whole.poses, split.poses)) propertyBroken("igtl", "poses depend on read sizes");
  if (whole.channels.size() != split.channels.size()) {
    propertyBroken("igtl", "channel values depend on read sizes");
  }
  return 0;
}

}  // namespace microsim::fuzz
