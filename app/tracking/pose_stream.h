#pragma once
// A recorded raw tracker stream: every accepted pose and channel value in arrival order,
// as `microsim-cli track --record FILE` writes it and ReplaySource plays it back (for
// calibration without the tracker, and for tests).
//
// JSON (version 1):
//   {"format": "microsim-tracker-stream", "version": 1,
//    "samples": [{"device": "Stylus", "time": 0.01, "matrix": [16 numbers, 4 by 4 row-major, mm]},
//                {"channel": "Grip", "time": 0.02, "value": 0.4}, ...]}
// time in s on the source's clock, non-decreasing per device/channel is NOT required
// here (the replay's PoseFilter refuses what a live link would refuse).
//
// Files are written one sample per line, each line flushed as it is appended
// (PoseStreamWriter): the header line, then "{sample}", then ",{sample}" per line, then
// "]}". A process killed while recording leaves a file that ends inside or after a line;
// reading it gives Truncated with every complete line's sample kept.

#include "tracking/tracker_types.h"

#include <QFile>
#include <QString>

#include <variant>
#include <vector>

namespace microsim::tracking {

using StreamSample = std::variant<RawPose, ChannelValue>;

struct PoseStream {
  std::vector<StreamSample> samples;  ///< in arrival order
};

enum class PoseStreamError {
  None,
  CannotOpen,   ///< the file could not be read or written
  NotJson,      ///< not a JSON object
  WrongFormat,  ///< "format" is not "microsim-tracker-stream" or the version is newer
  BadSample,    ///< a sample lacks a field or has a wrong one (see PoseStreamStatus)
  Truncated,    ///< the writer was stopped before the end; `out` holds every complete sample
  CannotWrite,  ///< a sample could not be written (disk full, ...)
};

struct PoseStreamStatus {
  PoseStreamError error = PoseStreamError::None;
  int sample = -1;  ///< with BadSample: the index of the sample at fault
  QString field;    ///< with BadSample: the field at fault ("matrix", "time", ...)
  bool ok() const { return error == PoseStreamError::None; }
};

/// Time (s) of a sample on the source's clock.
double sampleTime(const StreamSample& sample);

QByteArray encodePoseStream(const PoseStream& stream);
PoseStreamStatus decodePoseStream(const QByteArray& json, PoseStream& out);
PoseStreamStatus readPoseStream(const QString& path, PoseStream& out);
PoseStreamStatus writePoseStream(const QString& path, const PoseStream& stream);

/// Writes a stream as it arrives, one flushed line per sample (see the top of this file).
class PoseStreamWriter {
 public:
  /// Creates or empties `path` and writes the header line.
  PoseStreamStatus open(const QString& path);
  PoseStreamStatus append(const StreamSample& sample);
  /// Writes the closing line and closes the file.
  PoseStreamStatus finish();
  bool isOpen() const { return file_.isOpen(); }

 private:
  PoseStreamStatus writeLine(const QByteArray& line);

  QFile file_;
  bool first_ = true;
};

}  // namespace microsim::tracking
