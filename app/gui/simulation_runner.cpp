#include "gui/simulation_runner.h"

#include "microsim/sim/scene/recorded_scene.h"

#include <QJsonDocument>

#include <pthread.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>

namespace microsim::gui {

namespace {

using Clock = std::chrono::steady_clock;

// median and 99th percentile of step times (ms); sorts its argument
std::pair<double, double> medianAndP99(std::vector<double>& ms) {
  if (ms.empty()) return {0.0, 0.0};
  std::sort(ms.begin(), ms.end());
  const auto at = [&](double q) {
    const auto i = static_cast<std::size_t>(std::lround(q * static_cast<double>(ms.size() - 1)));
    return ms[std::min(i, ms.size() - 1)];
  };
  return {at(0.5), at(0.99)};
}

const std::vector<std::array<int, 3>> kNoTriangles;

}  // namespace

SimulationRunner::SimulationRunner(QObject* parent) : QObject(parent) {
  qRegisterMetaType<sim::SceneEvent>();
  qRegisterMetaType<sim::InputFrame>();
}

SimulationRunner::~SimulationRunner() { stop(); }

bool SimulationRunner::load(const QString& scenePath, sim::StepMode mode, sim::SceneError* error) {
  reset();
  auto opened = sim::openScene(scenePath.toStdString(), mode);
  if (auto* e = std::get_if<sim::SceneError>(&opened)) {
    if (error) *error = *e;
    return false;
  }
  adopt(std::move(std::get<std::unique_ptr<sim::Scene>>(opened)), scenePath);
  return true;
}

void SimulationRunner::load(const sim::SceneDef& def, sim::StepMode mode) {
  reset();
  adopt(std::make_unique<sim::Scene>(def, mode), QString::fromStdString(def.file));
}

// stops any run and forgets the scene and everything it produced
void SimulationRunner::reset() {
  stop();
  scene_.reset();
  {
    const std::lock_guard lock(snapshotMutex_);
    latest_.reset();
  }
  {
    const std::lock_guard lock(resultsMutex_);
    events_.clear();
    pierces_.clear();
    consumed_.clear();
  }
  {
    const std::lock_guard lock(inputMutex_);
    haveFrame_ = false;
    latestFrame_ = {};
  }
  steps_ = 0;
  hash_ = 0;
}

void SimulationRunner::adopt(std::unique_ptr<sim::Scene> scene, const QString& scenePath) {
  scene_ = std::move(scene);
  scenePath_ = scenePath;
  hash_ = scene_->hash();
  publish();
}

void SimulationRunner::start() {
  if (!scene_ || running_) return;
  launch([this] { runLive(); });
}

void SimulationRunner::replay(std::vector<sim::InputFrame> frames) {
  if (!scene_) return;
  stop();
  launch([this, frames = std::move(frames)] { runReplay(frames); });
}

void SimulationRunner::launch(std::function<void()> body) {
  if (thread_.joinable()) thread_.join();  // a replay that ended by itself
  stopRequested_ = false;
  running_ = true;
  openRecording();
  // A std::thread rather than a QThread: the step loop needs no Qt event loop, and joining
  // it is a synchronisation ThreadSanitizer follows (QThread::wait() waits on Qt's own
  // futex-based locks, which it cannot see). Signals emitted on it reach receivers in other
  // threads queued, as from any thread.
  thread_ = std::thread([body = std::move(body)] {
    pthread_setname_np(pthread_self(), "simulation");  // for debuggers and perf
    body();
  });
}

void SimulationRunner::stop() {
  if (thread_.joinable()) {
    {
      const std::lock_guard lock(inputMutex_);
      stopRequested_ = true;
    }
    wake_.notify_all();
    thread_.join();
    running_ = false;
  }
  finishRecording();
}

void SimulationRunner::setRecordingFile(const QString& path, const QJsonObject& metadata) {
  recordingPath_ = path;
  recordingMetadata_ = metadata;
}

sim::RecordingStatus SimulationRunner::recordingStatus() const {
  const std::lock_guard lock(resultsMutex_);
  return recordingStatus_;
}

void SimulationRunner::openRecording() {
  const std::lock_guard lock(resultsMutex_);
  recordingStatus_ = {};
  if (recordingPath_.isEmpty() || writer_.isOpen()) return;
  // the header names the scene (absolute, with its digest), so that `microsim-cli run` and
  // `score` replay the file on the scene it was made on without being told; the metadata is
  // what the caller adds (the app: the lesson, and the solver when the settings changed it)
  const std::string metadata =
      recordingMetadata_.isEmpty() ? std::string()
                                   : QJsonDocument(recordingMetadata_).toJson(QJsonDocument::Compact).toStdString();
  recordingStatus_ = writer_.open(recordingPath_.toStdString(), sim::recordScene(scenePath_.toStdString()), metadata);
}

void SimulationRunner::finishRecording() {
  const std::lock_guard lock(resultsMutex_);
  if (!writer_.isOpen()) return;
  const sim::RecordingStatus s = writer_.finish();
  if (recordingStatus_.ok()) recordingStatus_ = s;
}

void SimulationRunner::submitFrame(const sim::InputFrame& frame) {
  const std::lock_guard lock(inputMutex_);
  latestFrame_ = frame;
  haveFrame_ = true;
}

std::shared_ptr<const sim::RenderSnapshot> SimulationRunner::latestSnapshot() const {
  const std::lock_guard lock(snapshotMutex_);
  return latest_;
}

std::vector<sim::SceneEvent> SimulationRunner::events() const {
  const std::lock_guard lock(resultsMutex_);
  return events_;
}

std::vector<sim::PierceEvent> SimulationRunner::pierces() const {
  const std::lock_guard lock(resultsMutex_);
  return pierces_;
}

std::vector<sim::InputFrame> SimulationRunner::consumedFrames() const {
  const std::lock_guard lock(resultsMutex_);
  return consumed_;
}

const sim::SceneDef* SimulationRunner::sceneDef() const { return scene_ ? &scene_->def() : nullptr; }

const std::vector<std::array<int, 3>>& SimulationRunner::tissueTriangles() const {
  return scene_ ? scene_->tissue().triangles() : kNoTriangles;
}

void SimulationRunner::publish() {
  std::shared_ptr<sim::RenderSnapshot> next = recycler_.take();
  sim::fillSnapshot(*scene_, *next);
  {
    const std::lock_guard lock(snapshotMutex_);
    latest_.swap(next);
  }
  // `next` is now the previous snapshot: released here, outside the lock, it goes back to the
  // recycler unless a reader still holds it
}

void SimulationRunner::stepOnce(const sim::InputFrame& frame, std::vector<double>* times) {
  const std::size_t eventsBefore = scene_->events().size();
  const sim::StepReport report = scene_->step(frame);
  if (times) times->push_back(report.times.total * 1000.0);
  steps_ = scene_->steps();

  std::vector<sim::SceneEvent> added;
  {
    const std::lock_guard lock(resultsMutex_);
    consumed_.push_back(frame);
    if (writer_.isOpen() && recordingStatus_.ok()) recordingStatus_ = writer_.append(frame);
    const auto& all = scene_->events();
    if (all.size() > eventsBefore) {
      added.assign(all.begin() + static_cast<std::ptrdiff_t>(eventsBefore), all.end());
      events_.insert(events_.end(), added.begin(), added.end());
    }
    if (scene_->pierces().size() != pierces_.size()) pierces_ = scene_->pierces();
  }
  publish();
  for (const sim::SceneEvent& e : added) Q_EMIT sceneEvent(e);
  Q_EMIT snapshotReady();
}

void SimulationRunner::runLive() {
  const auto dt = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(scene_->dt()));
  std::vector<double> times;
  auto next = Clock::now();
  auto lastReport = next;
  sim::InputFrame frame;  // untracked hands until a source submits a frame
  for (auto& h : frame.hands) h.tracked = false;
  while (true) {
    {
      std::unique_lock lock(inputMutex_);
      wake_.wait_until(lock, next, [this] { return stopRequested_.load(); });
      if (stopRequested_) break;
      if (haveFrame_) frame = latestFrame_;
    }
    stepOnce(frame, &times);
    next += dt;
    const auto now = Clock::now();
    if (now > next + dt) next = now;  // behind by more than a step: do not race to catch up
    if (now - lastReport >= std::chrono::seconds(1)) {
      const auto [median, p99] = medianAndP99(times);
      times.clear();
      lastReport = now;
      Q_EMIT stepTimes(median, p99);
    }
  }
  hash_ = scene_->hash();
}

void SimulationRunner::runReplay(const std::vector<sim::InputFrame>& frames) {
  for (const sim::InputFrame& f : frames) {
    if (stopRequested_) break;
    stepOnce(f, nullptr);
  }
  hash_ = scene_->hash();
  finishRecording();
  running_ = false;
  Q_EMIT replayFinished();
}

}  // namespace microsim::gui
