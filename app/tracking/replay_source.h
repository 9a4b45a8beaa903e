#pragma once
// A TrackerSource that plays a recorded file back: either a simulation recording (.msrec,
// every InputFrame of an attempt, emitted as frameReady) or a raw tracker stream
// (tracking/pose_stream.h, emitted as poseAccepted / channelAccepted and, through the
// DeviceMapping, as frameReady, exactly as a live OpenIGTLink link would).
//
// Pace: RealTime emits each sample when its time (relative to the first sample) has
// elapsed since start(); AsFastAsPossible emits `batch` samples per event-loop turn, so
// the receivers' thread stays responsive. The source lives on its owner's thread (no
// thread of its own); raw samples pass through the same PoseFilter as a live link, so a
// recording of garbage is refused and counted the same way. finished() is emitted once,
// after the last sample.

#include "tracking/frame_assembler.h"
#include "tracking/pose_filter.h"
#include "tracking/pose_stream.h"
#include "tracking/tracker_source.h"

#include "microsim/sim/scene/recording.h"

#include <QElapsedTimer>
#include <QMutex>
#include <QTimer>

#include <deque>
#include <memory>
#include <vector>

namespace microsim::tracking {

enum class ReplayPace { RealTime, AsFastAsPossible };

struct ReplayConfig {
  DeviceMapping mapping;  ///< raw streams: devices and channels of the hands
  PoseLimits limits;      ///< raw streams: the gate every pose passes
  ReplayPace pace = ReplayPace::RealTime;
  int batch = 64;         ///< samples per event-loop turn with AsFastAsPossible
};

class ReplaySource : public TrackerSource {
  Q_OBJECT

 public:
  /// Plays a raw tracker stream.
  ReplaySource(PoseStream stream, ReplayConfig config, QObject* parent = nullptr);
  /// Plays the frames of a simulation recording (already in the scene frame).
  ReplaySource(std::vector<sim::InputFrame> frames, ReplayConfig config, QObject* parent = nullptr);
  ~ReplaySource() override;

  void start() override;
  void stop() override;
  TrackerStatus status() const override;

  std::size_t sampleCount() const;
  std::size_t played() const { return next_; }
  bool atEnd() const { return next_ >= sampleCount(); }
  /// True for a simulation recording (scene-frame frames), false for a raw tracker stream.
  bool playsRecording() const { return !rawStream_; }

 Q_SIGNALS:
  void finished();

 private:
  void tick();
  double dueTime(std::size_t i) const;  ///< s after start() at which sample i is emitted
  void play(std::size_t i);
  void playSample(const StreamSample& sample, double frameTime);
  void emitFrame(const sim::InputFrame& frame);
  void reject(Rejection r);

  ReplayConfig config_;
  PoseStream stream_;
  std::vector<sim::InputFrame> frames_;
  bool rawStream_ = true;
  PoseFilter filter_;
  FrameAssembler assembler_;
  QTimer timer_;
  QElapsedTimer clock_;
  std::size_t next_ = 0;
  double lastFrameTime_ = 0.0;
  bool running_ = false;
  std::deque<double> recent_;  ///< due times (s) of the poses accepted in the last second

  mutable QMutex mutex_;
  TrackerStatus status_;
};

enum class ReplayFileError {
  None,
  CannotOpen,     ///< missing or unreadable
  NotAReplay,     ///< neither a simulation recording nor a tracker stream
  Damaged,        ///< recognised, but the content is broken (see ReplayFileStatus)
};

struct ReplayFileStatus {
  ReplayFileError error = ReplayFileError::None;
  PoseStreamStatus stream;        ///< details for a tracker stream
  sim::RecordingError recording = sim::RecordingError::None;  ///< details for a recording
  bool ok() const { return error == ReplayFileError::None; }
};

/// Opens a .msrec recording (by its magic) or a tracker-stream JSON file. A truncated
/// recording still plays its complete frames (status stays ok).
std::unique_ptr<ReplaySource> openReplay(const QString& path, ReplayConfig config, ReplayFileStatus& status,
                                         QObject* parent = nullptr);

}  // namespace microsim::tracking
