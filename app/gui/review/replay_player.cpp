#include "gui/review/replay_player.h"

#include "gui/simulation_runner.h"
#include "microsim/sim/scene/recording.h"

#include <algorithm>
#include <span>
#include <variant>

namespace microsim::gui {

namespace {
// short enough that 4× plays in small chunks (a chunk is stepped at full speed)
constexpr int kTickMs = 25;
}  // namespace

ReplayPlayer::ReplayPlayer(QObject* parent) : QObject(parent), runner_(std::make_unique<SimulationRunner>()) {
  timer_.setInterval(kTickMs);
  connect(&timer_, &QTimer::timeout, this, &ReplayPlayer::tick);
  connect(runner_.get(), &SimulationRunner::replayFinished, this, &ReplayPlayer::onChunkDone);
}

ReplayPlayer::~ReplayPlayer() { stop(); }

ReplayLoad ReplayPlayer::load(const QString& scenePath, const QByteArray& recording) {
  stop();
  frames_.clear();
  def_.reset();
  target_ = 0;
  lastReported_ = -1;
  if (recording.isEmpty()) return ReplayLoad::NoRecording;
  sim::Recording decoded;
  const auto bytes = std::span(reinterpret_cast<const std::uint8_t*>(recording.constData()),
                               std::size_t(recording.size()));
  const sim::RecordingStatus status = sim::decodeRecording(bytes, decoded);
  if (!status.ok() && status.error != sim::RecordingError::Truncated) return ReplayLoad::BadRecording;
  // the definition is kept: a seek backward builds the scene from it again
  sim::SceneDefLoad loaded = sim::loadSceneDef(scenePath.toStdString());
  if (!std::holds_alternative<sim::SceneDef>(loaded)) return ReplayLoad::BadScene;
  def_ = std::move(std::get<sim::SceneDef>(loaded));
  runner_->load(*def_, sim::StepMode::Deterministic);
  frames_ = std::move(decoded.frames);
  return ReplayLoad::Ok;
}

int ReplayPlayer::position() const { return runner_->steps(); }

double ReplayPlayer::timeAt(int position) const {
  return def_ ? double(position) / def_->step.rateHz : 0.0;
}

void ReplayPlayer::play() {
  if (frames_.empty() || !def_) return;
  if (target_ >= frameCount()) seek(0);
  setPlaying(true);
  clock_.invalidate();  // started by the first tick with nothing being stepped
  tick();
}

void ReplayPlayer::pause() { setPlaying(false); }

void ReplayPlayer::togglePlay() {
  if (playing_) pause();
  else play();
}

void ReplayPlayer::stepForward() {
  pause();
  seek(target_ + 1);
}

void ReplayPlayer::stepBackward() {
  pause();
  seek(target_ - 1);
}

void ReplayPlayer::stop() {
  setPlaying(false);
  runner_->stop();
  target_ = runner_->steps();
  if (rerunning_) {
    rerunning_ = false;
    Q_EMIT rerunningChanged(false);
  }
  updateTimer();
}

void ReplayPlayer::setSpeed(double factor) {
  factor = std::clamp(factor, 0.25, 4.0);
  if (factor == speed_) return;
  // the clock goes on from the recording time it has reached, at the new pace
  if (clock_.isValid()) {
    clockOrigin_ += double(clock_.elapsed()) / 1000.0 * speed_;
    clock_.start();
  }
  speed_ = factor;
}

void ReplayPlayer::seek(int position) {
  if (frames_.empty() || !def_) return;
  position = std::clamp(position, 0, frameCount());
  if (position == target_) {
    if (!isBusy()) Q_EMIT settled(target_);
    return;
  }
  // the chunk in flight ends after the step it is in; a late replayFinished is counted
  runner_->stop();
  int at = runner_->steps();
  const bool backward = position < at;
  if (backward) {
    runner_->load(*def_, sim::StepMode::Deterministic);
    at = 0;
  }
  target_ = at;
  if (position > at) send(position);
  const bool rerun = backward && position > 0;
  if (rerun != rerunning_) {
    rerunning_ = rerun;
    Q_EMIT rerunningChanged(rerun);
  }
  clock_.invalidate();  // playback goes on from the new place once it is reached
  if (!isBusy()) {
    lastReported_ = position;
    Q_EMIT positionChanged(position);
    Q_EMIT settled(position);
  }
  updateTimer();
}

void ReplayPlayer::tick() {
  // progress of what is being stepped
  const int now = position();
  if (now != lastReported_) {
    lastReported_ = now;
    Q_EMIT positionChanged(now);
  }
  if (!playing_ || isBusy()) return;
  if (target_ >= frameCount()) {
    setPlaying(false);
    Q_EMIT finished();
    return;
  }
  if (!clock_.isValid()) restartClock();
  const double reached = clockOrigin_ + double(clock_.elapsed()) / 1000.0 * speed_;
  int end = target_;
  while (end < frameCount() && frames_[std::size_t(end)].time <= reached) ++end;
  if (end > target_) send(end);
}

// the clock starts at the time of the next frame to step, which therefore goes at once
void ReplayPlayer::restartClock() {
  clockOrigin_ = frames_[std::size_t(std::min(target_, frameCount() - 1))].time;
  clock_.start();
}

void ReplayPlayer::send(int end) {
  std::vector<sim::InputFrame> chunk(frames_.begin() + target_, frames_.begin() + end);
  target_ = end;
  ++pending_;
  runner_->replay(std::move(chunk));
  updateTimer();
}

void ReplayPlayer::onChunkDone() {
  pending_ = std::max(0, pending_ - 1);
  if (isBusy()) return;
  const int now = position();
  if (rerunning_) {
    rerunning_ = false;
    Q_EMIT rerunningChanged(false);
  }
  if (now != lastReported_) {
    lastReported_ = now;
    Q_EMIT positionChanged(now);
  }
  Q_EMIT settled(now);
  if (now >= frameCount()) {
    setPlaying(false);
    Q_EMIT finished();
  }
  updateTimer();
}

void ReplayPlayer::setPlaying(bool playing) {
  if (playing == playing_) return;
  playing_ = playing;
  updateTimer();
  Q_EMIT playingChanged(playing);
}

// the timer runs while there is something to hand over or to report
void ReplayPlayer::updateTimer() {
  if (playing_ || isBusy()) {
    if (!timer_.isActive()) timer_.start();
  } else {
    timer_.stop();
  }
}

}  // namespace microsim::gui
