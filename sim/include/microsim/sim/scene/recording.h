#pragma once
// Recordings of an attempt: every InputFrame, verbatim, so that a replay feeds the stepper
// the same bits and reaches the same states and the same score.
//
// File format (version 2, little-endian throughout):
//   magic     8 bytes  "MSIMREC" 0x1A
//   version   u16      2
//   hands     u16      kHandCount (2)
//   sceneLen  u32      length of the scene path that follows                 (version 2 on)
//   scene     sceneLen bytes, UTF-8: the scene file the recording was made on,
//             absolute as it was then (RecordedScene::path)                  (version 2 on)
//   digest    u64      FNV-1a 64 of that file's bytes then (RecordedScene::digest) (version 2 on)
//   metaLen   u32      length of the metadata that follows
//   metadata  metaLen bytes, opaque to the format (`microsim-cli run --record` stores JSON
//             naming its script)
//   frames    each: tag 'F' (u8), time (f64), then per hand: instrument (u8), tracked (u8),
//             position x y z (f64), orientation w x y z (f64), closure (f64)
//   end       tag 'E' (u8), frame count (u64), CRC-32 (IEEE) of every byte before the CRC (u32)
// Version 1 is the same without sceneLen, scene and digest; it is still read (its scene is
// not known), and always written as version 2.
//
// The scene is named by its absolute path, not as typed: a relative path means nothing once
// the working folder has changed. The digest tells a moved or copied scene file from an
// edited one: locateRecordedScene (recorded_scene.h) looks for the scene where it was, beside
// the recording and among the shipped scenes, and says whether what it found is the same.
//
// The writer appends frames as they happen and flushes at least every 0.1 s of attempt
// time, so a crash loses at most the frames of the last 0.1 s. A file without its end
// record is an unfinished attempt: the reader says Truncated and still returns every complete frame.

#include "microsim/sim/scene/input_frame.h"

#include <cstdint>
#include <cstdio>
#include <span>
#include <string>
#include <vector>

namespace microsim::sim {

inline constexpr std::uint16_t kRecordingVersion = 2;

/// The scene a recording was made on.
struct RecordedScene {
  std::string path;          ///< the scene file, absolute; empty: not known (a version-1 recording)
  std::uint64_t digest = 0;  ///< FNV-1a 64 of the file's bytes when it was recorded; 0: not known
  bool known() const { return !path.empty(); }
  bool operator==(const RecordedScene&) const = default;
};

struct Recording {
  RecordedScene scene;
  std::string metadata;
  std::vector<InputFrame> frames;
};

enum class RecordingError : std::uint8_t {
  None,
  CannotOpen,          ///< the file could not be opened (missing, permissions)
  CannotWrite,         ///< a write or flush failed (disk full)
  NotARecording,       ///< wrong magic: some other file
  UnsupportedVersion,  ///< a newer format than this build reads
  Truncated,           ///< no end record: an unfinished attempt; complete frames are returned
  ChecksumMismatch,    ///< the end record's CRC does not match the bytes: damaged
  Malformed,           ///< an unknown tag, a count that disagrees, or a frame that fails validateFrame
};

struct RecordingStatus {
  RecordingError error = RecordingError::None;
  std::uint64_t offset = 0;  ///< byte offset where reading stopped (for the message)
  bool ok() const { return error == RecordingError::None; }
};

/// Encodes a complete recording (with its end record) in memory.
std::vector<std::uint8_t> encodeRecording(const Recording& recording);

/// Decodes bytes; on Truncated `out` holds the complete frames before the cut.
RecordingStatus decodeRecording(std::span<const std::uint8_t> bytes, Recording& out);

/// Reads a file; on Truncated `out` holds the complete frames before the cut.
RecordingStatus readRecording(const std::string& path, Recording& out);

/// Streams frames to a file as an attempt runs.
class RecordingWriter {
 public:
  RecordingWriter() = default;
  ~RecordingWriter();  ///< closes without an end record when finish() was not called
  RecordingWriter(const RecordingWriter&) = delete;
  RecordingWriter& operator=(const RecordingWriter&) = delete;

  /// Starts the file at `path`: its header names `scene` (recordScene(scenePath) makes one).
  RecordingStatus open(const std::string& path, const RecordedScene& scene, const std::string& metadata);
  /// Appends one frame; flushes when 0.1 s of attempt time has passed since the last flush.
  RecordingStatus append(const InputFrame& frame);
  /// Writes the end record and closes the file.
  RecordingStatus finish();
  bool isOpen() const { return file_ != nullptr; }
  std::uint64_t frameCount() const { return frames_; }

 private:
  RecordingStatus write(std::span<const std::uint8_t> bytes);
  void closeFile();

  std::FILE* file_ = nullptr;
  std::uint32_t crc_ = 0;
  std::uint64_t frames_ = 0;
  std::uint64_t bytes_ = 0;
  double lastFlushTime_ = 0.0;
};

/// CRC-32 (IEEE 802.3, reflected, as zlib) continued from `crc` over `bytes`.
std::uint32_t crc32(std::span<const std::uint8_t> bytes, std::uint32_t crc = 0);

}  // namespace microsim::sim
