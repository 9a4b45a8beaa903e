#include "microsim/sim/scene/recording.h"

#include <array>
#include <bit>
#include <cstring>

namespace microsim::sim {

namespace {

constexpr std::array<std::uint8_t, 8> kMagic = {'M', 'S', 'I', 'M', 'R', 'E', 'C', 0x1A};
constexpr std::uint8_t kFrameTag = 'F';
constexpr std::uint8_t kEndTag = 'E';
constexpr std::size_t kHandBytes = 2 + 8 * 8;
constexpr std::size_t kFrameBytes = 1 + 8 + kHandCount * kHandBytes;
constexpr std::size_t kEndBytes = 1 + 8 + 4;
// s of attempt time: what a killed process may lose at most (10 frames at 100 Hz); one
// write(2) of ~1.4 kB per 0.1 s costs nothing beside a step
constexpr double kFlushInterval = 0.1;

static_assert(std::endian::native == std::endian::little,
              "recordings are little-endian; add byte swapping for this platform");

// little-endian encoding of fixed-size values
class Encoder {
 public:
  explicit Encoder(std::vector<std::uint8_t>& out) : out_(out) {}
  template <class T>
  void put(T value) {
    std::uint8_t bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    out_.insert(out_.end(), bytes, bytes + sizeof(T));
  }

 private:
  std::vector<std::uint8_t>& out_;
};

class Decoder {
 public:
  explicit Decoder(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}
  bool has(std::size_t n) const { return bytes_.size() - pos_ >= n; }
  // a length-prefixed run of bytes; false when the input ends first
  bool getText(std::string& out) {
    if (!has(4)) return false;
    const auto length = get<std::uint32_t>();
    if (!has(length)) return false;
    out.assign(reinterpret_cast<const char*>(bytes_.data() + pos_), length);
    pos_ += length;
    return true;
  }
  template <class T>
  T get() {
    T value;
    std::memcpy(&value, bytes_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return value;
  }
  std::size_t pos() const { return pos_; }
  std::span<const std::uint8_t> before(std::size_t end) const { return bytes_.first(end); }

 private:
  std::span<const std::uint8_t> bytes_;
  std::size_t pos_ = 0;
};

// a length-prefixed run of bytes (u32 length, then the bytes)
void putText(std::vector<std::uint8_t>& out, const std::string& text) {
  Encoder(out).put<std::uint32_t>(static_cast<std::uint32_t>(text.size()));
  out.insert(out.end(), text.begin(), text.end());
}

std::vector<std::uint8_t> encodeHeader(const RecordedScene& scene, const std::string& metadata) {
  std::vector<std::uint8_t> out(kMagic.begin(), kMagic.end());
  Encoder e(out);
  e.put<std::uint16_t>(kRecordingVersion);
  e.put<std::uint16_t>(kHandCount);
  putText(out, scene.path);
  e.put<std::uint64_t>(scene.digest);
  putText(out, metadata);
  return out;
}

void encodeFrame(Encoder& e, const InputFrame& frame) {
  e.put<std::uint8_t>(kFrameTag);
  e.put<double>(frame.time);
  for (const HandInput& h : frame.hands) {
    e.put<std::uint8_t>(static_cast<std::uint8_t>(h.instrument));
    e.put<std::uint8_t>(h.tracked ? 1 : 0);
    for (int i = 0; i < 3; ++i) e.put<double>(h.position[i]);
    e.put<double>(h.orientation.w());
    e.put<double>(h.orientation.x());
    e.put<double>(h.orientation.y());
    e.put<double>(h.orientation.z());
    e.put<double>(h.closure);
  }
}

bool decodeFrame(Decoder& d, InputFrame& frame) {
  frame.time = d.get<double>();
  for (HandInput& h : frame.hands) {
    const auto instrument = d.get<std::uint8_t>();
    const auto tracked = d.get<std::uint8_t>();
    if (instrument > static_cast<std::uint8_t>(Instrument::Scissors) || tracked > 1) return false;
    h.instrument = static_cast<Instrument>(instrument);
    h.tracked = tracked == 1;
    for (int i = 0; i < 3; ++i) h.position[i] = d.get<double>();
    const double w = d.get<double>();
    const double x = d.get<double>();
    const double y = d.get<double>();
    const double z = d.get<double>();
    h.orientation = Eigen::Quaterniond(w, x, y, z);
    h.closure = d.get<double>();
  }
  InputRejection why;
  return validateFrame(frame, why);
}

const std::array<std::uint32_t, 256>& crcTable() {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t i = 0; i < 256; ++i) {
      std::uint32_t c = i;
      for (int k = 0; k < 8; ++k) c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[i] = c;
    }
    return t;
  }();
  return table;
}

}  // namespace

std::uint32_t crc32(std::span<const std::uint8_t> bytes, std::uint32_t crc) {
  const auto& table = crcTable();
  crc = ~crc;
  for (std::uint8_t b : bytes) crc = table[(crc ^ b) & 0xffu] ^ (crc >> 8);
  return ~crc;
}

std::vector<std::uint8_t> encodeRecording(const Recording& recording) {
  std::vector<std::uint8_t> out = encodeHeader(recording.scene, recording.metadata);
  out.reserve(out.size() + recording.frames.size() * kFrameBytes + kEndBytes);
  Encoder e(out);
  for (const InputFrame& f : recording.frames) encodeFrame(e, f);
  e.put<std::uint8_t>(kEndTag);
  e.put<std::uint64_t>(recording.frames.size());
  e.put<std::uint32_t>(crc32(out));
  return out;
}

RecordingStatus decodeRecording(std::span<const std::uint8_t> bytes, Recording& out) {
  out = {};
  Decoder d(bytes);
  auto fail = [&](RecordingError error) { return RecordingStatus{error, d.pos()}; };

  // header
  if (!d.has(kMagic.size()) || !std::equal(kMagic.begin(), kMagic.end(), bytes.begin()))
    return fail(RecordingError::NotARecording);
  for (std::size_t i = 0; i < kMagic.size(); ++i) d.get<std::uint8_t>();
  if (!d.has(4)) return fail(RecordingError::Truncated);
  const auto version = d.get<std::uint16_t>();
  if (version > kRecordingVersion) return fail(RecordingError::UnsupportedVersion);
  if (version == 0 || d.get<std::uint16_t>() != kHandCount) return fail(RecordingError::Malformed);
  // version 1 names no scene
  if (version >= 2) {
    if (!d.getText(out.scene.path) || !d.has(8)) return fail(RecordingError::Truncated);
    out.scene.digest = d.get<std::uint64_t>();
  }
  if (!d.getText(out.metadata)) return fail(RecordingError::Truncated);

  // frames, then the end record
  while (d.has(1)) {
    const std::size_t tagAt = d.pos();
    const auto tag = d.get<std::uint8_t>();
    if (tag == kFrameTag) {
      if (!d.has(kFrameBytes - 1)) return {RecordingError::Truncated, tagAt};
      InputFrame frame;
      if (!decodeFrame(d, frame)) return {RecordingError::Malformed, tagAt};
      out.frames.push_back(frame);
    } else if (tag == kEndTag) {
      if (!d.has(kEndBytes - 1)) return {RecordingError::Truncated, tagAt};
      const auto count = d.get<std::uint64_t>();
      const std::size_t crcAt = d.pos();
      const auto crc = d.get<std::uint32_t>();
      if (crc != crc32(d.before(crcAt))) return {RecordingError::ChecksumMismatch, crcAt};
      if (count != out.frames.size() || d.has(1)) return {RecordingError::Malformed, crcAt};
      return {};
    } else {
      return {RecordingError::Malformed, tagAt};
    }
  }
  return fail(RecordingError::Truncated);
}

RecordingStatus readRecording(const std::string& path, Recording& out) {
  out = {};
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (f == nullptr) return {RecordingError::CannotOpen, 0};
  std::vector<std::uint8_t> bytes;
  std::uint8_t buffer[1 << 16];
  std::size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, f)) > 0) bytes.insert(bytes.end(), buffer, buffer + n);
  const bool failed = std::ferror(f) != 0;
  std::fclose(f);
  if (failed) return {RecordingError::CannotOpen, bytes.size()};
  return decodeRecording(bytes, out);
}

RecordingWriter::~RecordingWriter() { closeFile(); }

void RecordingWriter::closeFile() {
  if (file_ != nullptr) std::fclose(file_);
  file_ = nullptr;
}

RecordingStatus RecordingWriter::write(std::span<const std::uint8_t> bytes) {
  if (std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size())
    return {RecordingError::CannotWrite, bytes_};
  crc_ = crc32(bytes, crc_);
  bytes_ += bytes.size();
  return {};
}

RecordingStatus RecordingWriter::open(const std::string& path, const RecordedScene& scene, const std::string& metadata) {
  closeFile();
  crc_ = 0;
  frames_ = 0;
  bytes_ = 0;
  lastFlushTime_ = 0.0;
  file_ = std::fopen(path.c_str(), "wb");
  if (file_ == nullptr) return {RecordingError::CannotOpen, 0};
  const std::vector<std::uint8_t> header = encodeHeader(scene, metadata);
  RecordingStatus s = write(header);
  if (s.ok() && std::fflush(file_) != 0) s = {RecordingError::CannotWrite, bytes_};
  return s;
}

RecordingStatus RecordingWriter::append(const InputFrame& frame) {
  if (file_ == nullptr) return {RecordingError::CannotWrite, bytes_};
  InputRejection why;
  if (!validateFrame(frame, why)) return {RecordingError::Malformed, bytes_};
  std::vector<std::uint8_t> bytes;
  bytes.reserve(kFrameBytes);
  Encoder e(bytes);
  encodeFrame(e, frame);
  const RecordingStatus s = write(bytes);
  if (!s.ok()) return s;
  ++frames_;
  if (frame.time - lastFlushTime_ >= kFlushInterval) {
    lastFlushTime_ = frame.time;
    if (std::fflush(file_) != 0) return {RecordingError::CannotWrite, bytes_};
  }
  return {};
}

RecordingStatus RecordingWriter::finish() {
  if (file_ == nullptr) return {RecordingError::CannotWrite, bytes_};
  std::vector<std::uint8_t> end;
  Encoder e(end);
  e.put<std::uint8_t>(kEndTag);
  e.put<std::uint64_t>(frames_);
  RecordingStatus s = write(end);
  if (s.ok()) {
    std::vector<std::uint8_t> crc;
    Encoder(crc).put<std::uint32_t>(crc_);
    s = write(crc);
  }
  const bool flushed = std::fflush(file_) == 0;
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  if (s.ok() && (!flushed || !closed)) s = {RecordingError::CannotWrite, bytes_};
  return s;
}

}  // namespace microsim::sim
