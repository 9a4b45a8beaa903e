#include "gui/review/replay_player.h"

#include "gui/simulation_runner.h"
#include "microsim/sim/scene/recording.h"

#include <span>

namespace microsim::gui {

ReplayPlayer::ReplayPlayer(QObject* parent) : QObject(parent), runner_(std::make_unique<SimulationRunner>()) {
  timer_.setInterval(100);
  connect(&timer_, &QTimer::timeout, this, &ReplayPlayer::tick);
  connect(runner_.get(), &SimulationRunner::replayFinished, this, [this] {
    busy_ = false;
    if (next_ >= frames_.size()) {
      timer_.stop();
      Q_EMIT finished();
    }
  });
}

ReplayPlayer::~ReplayPlayer() { stop(); }

ReplayLoad ReplayPlayer::load(const QString& scenePath, const QByteArray& recording) {
  stop();
  frames_.clear();
  next_ = 0;
  if (recording.isEmpty()) return ReplayLoad::NoRecording;
  sim::Recording decoded;
  const auto bytes = std::span(reinterpret_cast<const std::uint8_t*>(recording.constData()),
                               std::size_t(recording.size()));
  const sim::RecordingStatus status = sim::decodeRecording(bytes, decoded);
  if (!status.ok() && status.error != sim::RecordingError::Truncated) return ReplayLoad::BadRecording;
  if (!runner_->load(scenePath, sim::StepMode::Deterministic)) return ReplayLoad::BadScene;
  frames_ = std::move(decoded.frames);
  return ReplayLoad::Ok;
}

void ReplayPlayer::play() {
  if (frames_.empty() || !runner_->isLoaded()) return;
  clock_.start();
  timer_.start();
  tick();
}

void ReplayPlayer::skipToEnd() {
  if (frames_.empty()) return;
  timer_.stop();
  if (!busy_) send(frames_.size());
  else timer_.start();  // the next tick after this chunk sends the rest
  clock_.invalidate();
}

void ReplayPlayer::stop() {
  timer_.stop();
  runner_->stop();
  busy_ = false;
}

void ReplayPlayer::tick() {
  if (busy_ || next_ >= frames_.size()) return;
  // the playback clock starts at the first frame's time; invalid after "to end"
  std::size_t end = frames_.size();
  if (clock_.isValid()) {
    const double now = frames_.front().time + double(clock_.elapsed()) / 1000.0;
    end = next_;
    while (end < frames_.size() && frames_[end].time <= now) ++end;
  }
  if (end > next_) send(end);
}

void ReplayPlayer::send(std::size_t end) {
  std::vector<sim::InputFrame> chunk(frames_.begin() + std::ptrdiff_t(next_), frames_.begin() + std::ptrdiff_t(end));
  next_ = end;
  busy_ = true;
  runner_->replay(std::move(chunk));
}

}  // namespace microsim::gui
