#pragma once
// Plays an attempt's stored recording back in its scene at the pace it was recorded.
//
// The scene is loaded Deterministic and fed the recording's frames in chunks through
// SimulationRunner::replay: each tick (100 ms) hands over the frames whose time the
// playback clock has reached, once the previous chunk is done. Every frame is stepped once,
// in order, so the states are those of `microsim-cli run` on the same recording (the score's
// replay); only the pace follows the wall clock. "To end" hands over the rest at once.

#include "microsim/sim/scene/input_frame.h"

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QTimer>

#include <memory>
#include <vector>

namespace microsim::gui {

class SimulationRunner;

enum class ReplayLoad { Ok, NoRecording, BadRecording, BadScene };

class ReplayPlayer : public QObject {
  Q_OBJECT

 public:
  explicit ReplayPlayer(QObject* parent = nullptr);
  ~ReplayPlayer() override;

  /// Loads `scenePath` and decodes `recording` (.msrec bytes; a truncated one plays its
  /// complete frames). Stops any playback.
  ReplayLoad load(const QString& scenePath, const QByteArray& recording);
  void play();
  /// Hands every remaining frame to the runner at once.
  void skipToEnd();
  void stop();

  SimulationRunner* runner() const { return runner_.get(); }
  int frameCount() const { return int(frames_.size()); }
  /// Frames handed to the runner so far.
  int framesSent() const { return int(next_); }
  bool isPlaying() const { return timer_.isActive(); }

 Q_SIGNALS:
  /// Every frame has been stepped.
  void finished();

 private:
  void tick();
  void send(std::size_t end);

  std::unique_ptr<SimulationRunner> runner_;
  std::vector<sim::InputFrame> frames_;
  std::size_t next_ = 0;
  bool busy_ = false;  ///< a chunk is being stepped
  QTimer timer_;
  QElapsedTimer clock_;
};

}  // namespace microsim::gui
