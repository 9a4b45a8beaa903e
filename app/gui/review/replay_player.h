#pragma once
// Plays an attempt's stored recording back in its scene: play and pause, 0.25×–4× speed, a
// step of one frame either way and a seek to any frame.
//
// The scene is stepped Deterministic by a SimulationRunner, fed the recording's frames in
// chunks through SimulationRunner::replay: while playing, each tick (25 ms) hands over the
// frames whose time the playback clock (wall clock × speed) has reached, once the previous
// chunk is done. Every frame is stepped once, in order, so the states are those of
// `microsim-cli run` on the same recording (the score's replay); only the pace follows the
// clock.
//
// Positions. The position is the number of frames stepped: 0 is the scene as loaded, p the
// state after frame p − 1 (SimulationRunner::steps()), frameCount() the end. A seek forward
// steps on from where the scene is. sim::Scene cannot be copied or restored, so a seek
// backward loads the scene again and steps it from the start up to the target on the
// runner's thread: the GUI stays live, rerunning() is true and positionChanged reports the
// progress, and the state reached is exactly that of a straight replay to the same frame.
//
// The runner emits replayFinished once for every replay it starts, also when a seek stopped
// it early; the player counts what it started, so a late signal of a stopped chunk is not
// taken for the end of the current one.

#include "microsim/sim/scene/input_frame.h"
#include "microsim/sim/scene/scene_def.h"

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QTimer>

#include <memory>
#include <optional>
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
  /// complete frames). Stops any playback; the position is 0.
  ReplayLoad load(const QString& scenePath, const QByteArray& recording);
  /// Plays from the position at speed(); from the start when at the end.
  void play();
  /// Stops handing frames over; the chunk being stepped finishes (settled follows).
  void pause();
  void togglePlay();
  /// Goes to `position` (clamped to 0..frameCount()), playing on if it was playing.
  void seek(int position);
  /// One frame on or back from where the player is going; playback pauses.
  void stepForward();
  void stepBackward();
  /// Hands every remaining frame to the runner at once.
  void skipToEnd() { seek(frameCount()); }
  /// Ends playback and any stepping.
  void stop();
  /// Playback speed, a factor on the recording's pace (0.25–4); playing on from where it is.
  void setSpeed(double factor);

  SimulationRunner* runner() const { return runner_.get(); }
  /// The scene the recording plays in; null before a load.
  const sim::SceneDef* sceneDef() const { return def_ ? &*def_ : nullptr; }
  /// The recording's frames as decoded.
  const std::vector<sim::InputFrame>& frames() const { return frames_; }
  int frameCount() const { return int(frames_.size()); }
  /// Frames stepped so far: the state the viewport shows.
  int position() const;
  /// Where the player is going: the position once every frame handed over is stepped.
  int target() const { return target_; }
  /// Frames handed to the runner so far (the same as target()).
  int framesSent() const { return target_; }
  /// Scene time (s) of a position: the steps' fixed dt apart.
  double timeAt(int position) const;
  double speed() const { return speed_; }
  bool isPlaying() const { return playing_; }
  /// The runner is stepping frames handed over.
  bool isBusy() const { return pending_ > 0; }
  /// A seek backward is stepping the scene again from the start.
  bool isRerunning() const { return rerunning_; }

 Q_SIGNALS:
  /// The position moved (during playback and a rerun, at most once a tick).
  void positionChanged(int position);
  /// The runner has stepped every frame handed over: the shown state is that at `position`.
  void settled(int position);
  void playingChanged(bool playing);
  void rerunningChanged(bool rerunning);
  /// The last frame has been stepped (playing, or after a seek to the end).
  void finished();

 private:
  void tick();
  void send(int end);
  void onChunkDone();
  void restartClock();
  void setPlaying(bool playing);
  void updateTimer();

  std::unique_ptr<SimulationRunner> runner_;
  std::optional<sim::SceneDef> def_;
  std::vector<sim::InputFrame> frames_;
  int target_ = 0;       ///< frames handed over (the position once settled)
  int pending_ = 0;      ///< replays started whose replayFinished has not arrived
  int lastReported_ = -1;
  bool playing_ = false;
  bool rerunning_ = false;
  double speed_ = 1.0;
  // the playback clock: recording time clockOrigin_ + elapsed × speed
  double clockOrigin_ = 0.0;
  QElapsedTimer clock_;
  QTimer timer_;
};

}  // namespace microsim::gui
