#pragma once
// The simulation thread (DESIGN.md §Data flow of one frame): owns a sim::Scene and steps it on
// its own thread, so the GUI thread draws at display rate and never waits on a step.
//
// Live (start): one step every 1/rate s of wall-clock time with the latest frame handed to
// submitFrame (before the first frame, an untracked one: the tools stay where they are). A
// step that overruns delays the next; more than one step behind, the schedule restarts from
// now rather than racing to catch up, so the scene's time falls behind instead of spiralling.
// Replay (replay): every given frame once, in order, as fast as possible; with a scene loaded
// in StepMode::Deterministic the states are bit-identical to `microsim-cli run` on the same
// frames (stateHash()).
//
// Hand-over: after each step the thread fills a RenderSnapshot no reader holds (from the
// SnapshotRecycler) and swaps it in as the latest under a lock held only for the pointer swap;
// a reader keeps its shared_ptr as long as it likes, and the buffer returns to the recycler
// when the last holder lets go.
// Events, pierces and the consumed frames are copied out under a lock after each step.
// Signals are emitted from the simulation thread (queued to receivers in other threads).

#include "gui/snapshot_recycler.h"
#include "microsim/sim/scene/input_frame.h"
#include "tracking/input_frame_metatype.h"
#include "microsim/sim/scene/recording.h"
#include "microsim/sim/scene/render_snapshot.h"
#include "microsim/sim/scene/scene.h"

#include <QJsonObject>
#include <QMetaType>
#include <QObject>
#include <QString>

#include <array>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace microsim::gui {

class SimulationRunner : public QObject {
  Q_OBJECT

 public:
  explicit SimulationRunner(QObject* parent = nullptr);
  ~SimulationRunner() override;  ///< stops and joins the thread, finishes a recording

  /// Loads a scene file (Deterministic for attempts and replays, so that an attempt's recording
  /// replays to what was shown; RealTime stops each tissue solve at the step budget), stopping any run
  /// first. Returns false and fills `error` when the file does not load; the previous scene
  /// is then gone too.
  bool load(const QString& scenePath, sim::StepMode mode, sim::SceneError* error = nullptr);
  /// The same from a scene definition already loaded (and perhaps changed in memory); its
  /// `file` names the scene in recordings.
  void load(const sim::SceneDef& def, sim::StepMode mode);
  /// Live: steps at the scene's rate from the latest submitted frame. No-op without a scene or
  /// while running.
  void start();
  /// Ends a live run or a replay after the step in progress; joins the thread; finishes the
  /// recording file. Safe to call when idle.
  void stop();
  /// Steps every frame once on the simulation thread as fast as possible, then emits
  /// replayFinished. Stops a live run first.
  void replay(std::vector<sim::InputFrame> frames);
  /// Records every consumed InputFrame to this file from the next start()/replay() on (empty:
  /// no recording); the file is finished on stop(), at the end of a replay, or on destruction.
  /// Its header names the loaded scene; `metadata` (empty: none) goes in as compact JSON.
  void setRecordingFile(const QString& path, const QJsonObject& metadata = {});
  /// The recording's state (CannotOpen / CannotWrite when writing failed).
  sim::RecordingStatus recordingStatus() const;

  bool isLoaded() const { return scene_ != nullptr; }
  bool isRunning() const { return running_.load(); }
  /// The newest snapshot; null before load. Never waits on a step.
  std::shared_ptr<const sim::RenderSnapshot> latestSnapshot() const;
  /// Thread-safe copies of the scene's results so far.
  std::vector<sim::SceneEvent> events() const;
  std::vector<sim::PierceEvent> pierces() const;
  std::vector<sim::InputFrame> consumedFrames() const;
  /// Steps taken so far.
  int steps() const { return steps_.load(); }
  /// The scene's golden-state hash (sim::Scene::hash) after load and at the end of each run
  /// (stop() or the end of a replay).
  std::uint64_t stateHash() const { return hash_.load(); }
  /// The scene's static part (tissue triangles, jaw meshes, camera); valid after load, and
  /// unchanged by steps. Null before load.
  const sim::SceneDef* sceneDef() const;
  /// The tissue's triangles (static), as sim::Scene::tissue().triangles(); empty before load.
  const std::vector<std::array<int, 3>>& tissueTriangles() const;

 public Q_SLOTS:
  /// The frame the next live steps use (from any tracker source, any thread).
  void submitFrame(const microsim::sim::InputFrame& frame);

 Q_SIGNALS:
  void snapshotReady();  ///< a new snapshot is available
  void sceneEvent(const microsim::sim::SceneEvent& e);
  void replayFinished();
  /// Wall-clock step times over the last second (ms), emitted once a second while live.
  void stepTimes(double medianMs, double p99Ms);

 private:
  void runLive();
  void runReplay(const std::vector<sim::InputFrame>& frames);
  void stepOnce(const sim::InputFrame& frame, std::vector<double>* times);
  void publish();
  void openRecording();
  void finishRecording();
  void launch(std::function<void()> body);
  void reset();
  void adopt(std::unique_ptr<sim::Scene> scene, const QString& scenePath);

  std::unique_ptr<sim::Scene> scene_;  // touched only by the simulation thread while running
  QString scenePath_;
  std::thread thread_;
  std::atomic<bool> running_{false};
  std::atomic<bool> stopRequested_{false};
  std::atomic<int> steps_{0};
  std::atomic<std::uint64_t> hash_{0};

  mutable std::mutex inputMutex_;  // also guards the live loop's wait
  std::condition_variable wake_;
  sim::InputFrame latestFrame_;
  bool haveFrame_ = false;

  mutable std::mutex snapshotMutex_;
  std::shared_ptr<sim::RenderSnapshot> latest_;
  SnapshotRecycler recycler_;

  mutable std::mutex resultsMutex_;
  std::vector<sim::SceneEvent> events_;
  std::vector<sim::PierceEvent> pierces_;
  std::vector<sim::InputFrame> consumed_;

  QString recordingPath_;
  QJsonObject recordingMetadata_;
  sim::RecordingWriter writer_;
  sim::RecordingStatus recordingStatus_;
};

}  // namespace microsim::gui

Q_DECLARE_METATYPE(microsim::sim::SceneEvent)
