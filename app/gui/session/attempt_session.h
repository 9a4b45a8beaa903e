#pragma once
// One attempt at a lesson, without widgets: the controller the attempt page displays
// (DESIGN.md §18, fooyin's engine handler). It owns
//   - the lesson's rubric and scene definition, loaded once, the solver settings applied in
//     memory (settings/scene_overrides.h);
//   - the SimulationRunner that steps the scene on its own thread and writes the attempt's
//     recording as it goes;
//   - the lesson's progress, polled every 100 ms while the scene runs;
//   - an AttemptWorker on a QThread of its own: the history connection and the graded
//     replay. Nothing in this class calls the database; every history read and write of
//     the attempt happens on that thread.
//
// Life of an attempt:
//   prepare    loads rubric and scene and posts "begin" to the worker (begun follows, with
//              the attempt's id, or 0 when it is not stored);
//   startLive  steps at the scene's rate from the frames submitted to the runner, or
//   replay     steps the given frames as fast as possible on a fresh scene (the recording
//              restarts with them);
//   finish     stops (the recording file is complete) and posts the graded replay, which
//              stores score and recording in one transaction: finished;
//   abandon    stops; the history marks the attempt abandoned: abandoned;
//   stop, or destruction, without finish or abandon: the attempt stays in progress, and
//              once the worker's connection is closed (on destruction) the next open of the
//              history marks it interrupted, as after a crash.
// The destructor waits until the worker has done what was posted (a graded replay too).

#include "gui/session/attempt_result.h"
#include "gui/settings/scene_overrides.h"
#include "lesson/lesson.h"

#include "microsim/assessment/scoring/rubric.h"
#include "microsim/sim/scene/input_frame.h"
#include "microsim/sim/scene/scene_def.h"

#include <QObject>
#include <QThread>

#include <memory>
#include <vector>

class QTimer;

namespace microsim::gui {

class AttemptRequests;
class AttemptWorker;
class SimulationRunner;

/// Everything an attempt is started from.
struct AttemptSetup {
  lesson::Lesson lesson;
  int lessonIndex = -1;
  assessment::AttemptMode mode = assessment::AttemptMode::Learn;
  assessment::Viewer viewer;       ///< userId 0: a guest, nothing is stored
  QString historyLocation;         ///< SQLite file or PostgreSQL URL; empty: no history
  settings::SolverOverride solver;
  QString recordingFolder;         ///< where the recording file is written
};

/// The lesson's steps as far as the attempt has come.
struct AttemptProgress {
  int stepsDone = 0;            ///< steps whose conditions are met, in order
  std::vector<bool> guidesHit;  ///< per lesson guide: a pierce within 0.1 mm of its target
  int emptyGraspHand = -1;      ///< the hand whose latest grasp closed on nothing (progress.h), or −1
  int threadCuts = 0;              ///< the scissors' cuts so far (progress.h)
  double lastCutEndMm = -1.0;      ///< the latest cut's cut-end length, mm; −1 unanchored
  double threadTooShortMm = -1.0;  ///< the thread left on the needle once too short to tie, mm; or −1
  bool operator==(const AttemptProgress&) const = default;
};

class AttemptSession : public QObject {
  Q_OBJECT

 public:
  enum class State { Idle, Active, Scoring, Finished, Abandoned, Stopped };

  explicit AttemptSession(QObject* parent = nullptr);
  ~AttemptSession() override;

  /// Loads the rubric and the scene and begins the attempt (in the history, on the worker).
  /// False with `problem` when a file does not load or the solver setting is unknown.
  bool prepare(const AttemptSetup& setup, AttemptProblem* problem);
  void startLive();
  /// `finishAtEnd`: finish when the frames are done; else the attempt stays open and
  /// replayEnded follows.
  void replay(std::vector<sim::InputFrame> frames, bool finishAtEnd = true);
  void finish();
  void abandon();
  /// Ends the run without a verdict (see above).
  void stop();

  State state() const { return state_; }
  bool isActive() const { return state_ == State::Active; }
  /// 0 until begun has come, and when the attempt is not stored.
  qint64 attemptId() const { return attemptId_; }
  const AttemptSetup& setup() const { return setup_; }
  const AttemptProgress& progress() const { return progress_; }
  /// The scene as it runs (solver settings applied); valid after prepare.
  const sim::SceneDef& sceneDef() const { return def_; }
  SimulationRunner* runner() const { return runner_.get(); }
  QString recordingPath() const { return recordingPath_; }

 Q_SIGNALS:
  /// The history has begun the attempt (its id), or will not store it (0).
  void begun(qint64 attemptId);
  void progressed(const microsim::gui::AttemptProgress& progress);
  /// A replay that does not finish the attempt has stepped its last frame.
  void replayEnded();
  void finished(const microsim::gui::AttemptResult& result);
  /// After abandon(): `stored` when the history marked the attempt abandoned.
  void abandoned(bool stored);
  /// The history refused something (HistoryUnavailable, AbandonNotStored); the attempt
  /// goes on.
  void failed(const microsim::gui::AttemptProblem& problem);

 private:
  bool loadLesson(const AttemptSetup& setup, AttemptProblem* problem);
  void startRecording();
  void startWorker();
  void poll();
  void stopRunning();
  void shutDownWorker();

  AttemptSetup setup_;
  assessment::Rubric rubric_;
  sim::SceneDef def_;
  std::unique_ptr<SimulationRunner> runner_;
  QTimer* progressTimer_ = nullptr;
  std::unique_ptr<AttemptRequests> requests_;  // to the worker, queued
  QThread thread_;
  AttemptWorker* worker_ = nullptr;  // lives on thread_, deleted there when it finishes

  State state_ = State::Idle;
  QString recordingPath_;
  qint64 attemptId_ = 0;
  bool replaying_ = false;
  bool finishAtEnd_ = true;
  AttemptProgress progress_;
  std::vector<float> restPositions_;
  double maxDisplacementMm_ = 0.0;
};

}  // namespace microsim::gui

Q_DECLARE_METATYPE(microsim::gui::AttemptProgress)
