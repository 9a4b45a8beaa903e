#include "tracking/igtl_decoder.h"

#include <igtl_header.h>
#include <igtl_position.h>
#include <igtl_sensor.h>
#include <igtl_tdata.h>
#include <igtl_transform.h>
#include <igtl_util.h>

#include <cmath>
#include <cstddef>
#include <cstring>

namespace microsim::tracking {

namespace {

bool printable(char c) { return c >= 0x20 && c < 0x7f; }

// a fixed-size, NUL-padded ASCII field: printable up to the first NUL, NUL after it
bool plausibleName(const char* field, int size, bool mayBeEmpty) {
  int length = 0;
  while (length < size && field[length] != '\0') {
    if (!printable(field[length])) return false;
    ++length;
  }
  for (int i = length; i < size; ++i)
    if (field[i] != '\0') return false;
  return mayBeEmpty || length > 0;
}

std::string fieldString(const char* field, int size) {
  int length = 0;
  while (length < size && field[length] != '\0') ++length;
  return std::string(field, static_cast<std::size_t>(length));
}

igtl_header readHeader(const std::uint8_t* bytes) {
  igtl_header h;
  std::memcpy(&h, bytes, sizeof(h));
  igtl_header_convert_byte_order(&h);
  return h;
}

bool plausibleHeader(const igtl_header& h, std::uint64_t maxBody) {
  return (h.version == 1 || h.version == 2) && plausibleName(h.name, IGTL_HEADER_TYPE_SIZE, false) &&
         plausibleName(h.device_name, IGTL_HEADER_NAME_SIZE, true) && h.body_size <= maxBody;
}

double timestampSeconds(std::uint64_t ts, double receiveTime) {
  if (ts == 0) return receiveTime;
  const auto sec = static_cast<double>(ts >> 32);
  const auto frac = static_cast<double>(ts & 0xffffffffu);
  return sec + frac / 4294967296.0;
}

// column-major 3 by 4 (rotation columns, then translation) into a homogeneous matrix;
// `m` must be an aligned copy (message bodies are byte buffers with no alignment)
Eigen::Matrix4d fromTransform(const igtl_float32* m) {
  Eigen::Matrix4d out = Eigen::Matrix4d::Identity();
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 3; ++r) out(r, c) = static_cast<double>(m[c * 3 + r]);
  return out;
}

}  // namespace

void IgtlDecoder::feed(std::span<const std::uint8_t> bytes, double receiveTime, IgtlDecodeOutput& out) {
  buffer_.insert(buffer_.end(), bytes.begin(), bytes.end());
  for (;;) {
    const std::size_t available = buffer_.size() - start_;
    if (available < static_cast<std::size_t>(kIgtlHeaderSize)) break;
    const std::uint8_t* head = buffer_.data() + start_;
    const igtl_header h = readHeader(head);

    // garbage: count once, then slide byte by byte to the next plausible header
    if (!plausibleHeader(h, maxBodyBytes_)) {
      if (!resyncing_) out.add(Rejection::BadHeader);
      resyncing_ = true;
      ++start_;
      continue;
    }
    if (available < kIgtlHeaderSize + h.body_size) break;
    resyncing_ = false;

    const std::uint8_t* body = head + kIgtlHeaderSize;
    const igtl_uint64 crc = crc64(const_cast<unsigned char*>(body), h.body_size, 0ULL);
    if (crc != h.crc)
      out.add(Rejection::BadCrc);
    else
      decodeBody(head, body, h.body_size, receiveTime, out);
    start_ += kIgtlHeaderSize + static_cast<std::size_t>(h.body_size);
  }

  // drop consumed bytes once they dominate the buffer
  if (start_ > 0 && start_ * 2 >= buffer_.size()) {
    buffer_.erase(buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(start_));
    start_ = 0;
  }
}

void IgtlDecoder::endOfStream(IgtlDecodeOutput& out) {
  if (buffered() > 0 && !resyncing_) out.add(Rejection::Truncated);
  buffer_.clear();
  start_ = 0;
  resyncing_ = false;
}

void IgtlDecoder::decodeBody(const std::uint8_t* headerBytes, const std::uint8_t* body, std::uint64_t size,
                             double receiveTime, IgtlDecodeOutput& out) const {
  const igtl_header h = readHeader(headerBytes);
  const std::string type = fieldString(h.name, IGTL_HEADER_TYPE_SIZE);
  const std::string device = fieldString(h.device_name, IGTL_HEADER_NAME_SIZE);
  const double time = timestampSeconds(h.timestamp, receiveTime);

  if (type == "TRANSFORM") {
    if (size != IGTL_TRANSFORM_SIZE) {
      out.add(Rejection::WrongBodySize);
      return;
    }
    igtl_float32 m[12];
    std::memcpy(m, body, sizeof(m));
    igtl_transform_convert_byte_order(m);
    out.add(RawPose{device, time, fromTransform(m), true});
    return;
  }

  if (type == "POSITION") {
    igtl_position p{};
    p.quaternion[3] = 1.0f;
    std::memcpy(&p, body, static_cast<std::size_t>(std::min<std::uint64_t>(size, sizeof(p))));
    bool hasRotation = true;
    if (size == IGTL_POSITION_MESSAGE_DEFAULT_SIZE) {
      igtl_position_convert_byte_order(&p);
    } else if (size == IGTL_POSITION_MESSAGE_WITH_QUATERNION3_SIZE) {
      igtl_position_convert_byte_order_quaternion3(&p);
      const double q2 = double(p.quaternion[0]) * p.quaternion[0] + double(p.quaternion[1]) * p.quaternion[1] +
                        double(p.quaternion[2]) * p.quaternion[2];
      p.quaternion[3] = static_cast<igtl_float32>(q2 <= 1.0 ? std::sqrt(1.0 - q2) : std::nan(""));
    } else if (size == IGTL_POSITION_MESSAGE_POSITON_ONLY_SIZE) {
      igtl_position_convert_byte_order_position_only(&p);
      p.quaternion[0] = p.quaternion[1] = p.quaternion[2] = 0.0f;
      p.quaternion[3] = 1.0f;
      hasRotation = false;
    } else {
      out.add(Rejection::WrongBodySize);
      return;
    }
    // the quaternion is not normalised: a non-unit one gives a non-orthonormal block
    const double x = p.quaternion[0], y = p.quaternion[1], z = p.quaternion[2], w = p.quaternion[3];
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.block<3, 3>(0, 0) << 1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w),
        2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
        2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y);
    m.block<3, 1>(0, 3) << p.position[0], p.position[1], p.position[2];
    out.add(RawPose{device, time, m, hasRotation});
    return;
  }

  if (type == "TDATA") {
    if (size == 0 || size % IGTL_TDATA_ELEMENT_SIZE != 0) {
      out.add(Rejection::WrongBodySize);
      return;
    }
    const auto n = static_cast<std::size_t>(size / IGTL_TDATA_ELEMENT_SIZE);
    std::vector<igtl_tdata_element> elements(n);
    std::memcpy(elements.data(), body, static_cast<std::size_t>(size));
    igtl_tdata_convert_byte_order(elements.data(), static_cast<int>(n));
    for (const igtl_tdata_element& e : elements) {
      // the element struct is packed: copy its matrix out before reading floats from it
      igtl_float32 transform[12];
      std::memcpy(transform, reinterpret_cast<const unsigned char*>(&e) + offsetof(igtl_tdata_element, transform),
                  sizeof(transform));
      out.add(RawPose{fieldString(e.name, IGTL_TDATA_LEN_NAME), time, fromTransform(transform),
                      e.type != IGTL_TDATA_TYPE_3D});
    }
    return;
  }

  if (type == "SENSOR") {
    if (size < IGTL_SENSOR_HEADER_SIZE + 8) {
      out.add(Rejection::WrongBodySize);
      return;
    }
    igtl_sensor_header sh;
    std::memcpy(&sh, body, IGTL_SENSOR_HEADER_SIZE);
    if (sh.larray == 0 || size != IGTL_SENSOR_HEADER_SIZE + 8ull * sh.larray) {
      out.add(Rejection::WrongBodySize);
      return;
    }
    std::vector<igtl_float64> values(sh.larray);
    std::memcpy(values.data(), body + IGTL_SENSOR_HEADER_SIZE, std::size_t{8} * sh.larray);
    igtl_sensor_convert_byte_order(&sh, values.data());
    out.add(ChannelValue{device, time, values.front()});
    return;
  }

  out.add(Rejection::UnknownType);
}

std::vector<std::uint8_t> encodeIgtlHeader(const char* type, const std::string& device, std::uint64_t timestamp,
                                           std::span<const std::uint8_t> body, std::uint16_t version) {
  igtl_header h{};
  h.version = version;
  std::memcpy(h.name, type, strnlen(type, IGTL_HEADER_TYPE_SIZE));
  std::memcpy(h.device_name, device.data(), std::min<std::size_t>(device.size(), IGTL_HEADER_NAME_SIZE));
  h.timestamp = timestamp;
  h.body_size = body.size();
  h.crc = crc64(const_cast<unsigned char*>(body.data()), body.size(), 0ULL);
  igtl_header_convert_byte_order(&h);
  std::vector<std::uint8_t> out(kIgtlHeaderSize);
  std::memcpy(out.data(), &h, kIgtlHeaderSize);
  return out;
}

std::uint64_t toIgtlTimestamp(double seconds) {
  const double whole = std::floor(seconds);
  const auto frac = static_cast<std::uint64_t>((seconds - whole) * 4294967296.0);
  return (static_cast<std::uint64_t>(whole) << 32) | (frac & 0xffffffffu);
}

}  // namespace microsim::tracking
