#pragma once
// A tracker source turns some device (an OpenIGTLink server, the mouse, a recorded file)
// into timestamped InputFrames for the simulation, and reports the raw per-device poses
// for calibration and the `track` command. Sources may work on their own thread: their
// signals are emitted from it, so receivers in other threads get queued calls (Qt's
// automatic connection), and status() is safe to call from any thread.

#include "tracking/input_frame_metatype.h"
#include "tracking/tracker_types.h"

#include "microsim/sim/scene/input_frame.h"

#include <QMetaType>
#include <QObject>
#include <QString>

#include <cstdint>

namespace microsim::tracking {

/// What a status line shows.
struct TrackerStatus {
  bool connected = false;
  double rateHz = 0.0;            ///< accepted poses per second over the last second
  std::uint64_t accepted = 0;     ///< poses that passed every check
  std::uint64_t connections = 0;  ///< successful connections so far (1 + reconnects)
  RejectionCounts rejected;       ///< refused messages and poses, by reason
  QString lastError;              ///< the last link error as the system reported it; empty if none

  std::uint64_t dropped() const { return rejected.total(); }
};

class TrackerSource : public QObject {
  Q_OBJECT

 public:
  using QObject::QObject;
  ~TrackerSource() override = default;

  /// Begins producing (connects, opens the file, ...). Returns at once.
  virtual void start() = 0;
  /// Stops producing; no signal is emitted after it returns.
  virtual void stop() = 0;
  virtual TrackerStatus status() const = 0;

 Q_SIGNALS:
  /// A frame for the simulation: tracker-frame poses of both hands, time in s since start().
  void frameReady(const microsim::sim::InputFrame& frame);
  /// Every accepted pose, mapped to a hand or not.
  void poseAccepted(const microsim::tracking::RawPose& pose);
  /// Every accepted channel value.
  void channelAccepted(const microsim::tracking::ChannelValue& value);
  /// A message or pose was refused (already counted in status()).
  void rejected(microsim::tracking::Rejection reason);
  void connectedChanged(bool connected);
  /// The link is down: a connection attempt failed or an open link closed (see status().lastError).
  void linkDown();
};

}  // namespace microsim::tracking

Q_DECLARE_METATYPE(microsim::tracking::RawPose)
Q_DECLARE_METATYPE(microsim::tracking::ChannelValue)
Q_DECLARE_METATYPE(microsim::tracking::Rejection)
