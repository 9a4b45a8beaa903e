#pragma once
// One attempt at a lesson: the microscope viewport on the lesson's scene, the steps with a tick
// as each success condition is met (lesson/progress.h), and in Learn mode the lesson's guides
// (target rings and ideal needle directions; none in Test mode).
//
// Life of an attempt:
//   begin      loads the scene (with the solver settings applied, scene_overrides.h) and the
//              rubric, and begins the attempt in the history (status in_progress);
//   startLive  steps the scene at its rate from the keyboard/mouse tool source, or
//   replay     steps the given frames as fast as possible (a fresh deterministic scene);
//              either way every consumed frame is appended to the attempt's recording file
//              as it goes (a crash leaves a readable, truncated recording);
//   finish     stops, replays the finished recording deterministically to score it against
//              the rubric (so the stored score is what `microsim-cli score` gives for the same
//              recording), stores score and recording in one transaction, and emits finished;
//   abandon    stops without a score: the attempt stays in_progress and the history marks it
//              interrupted when it is next opened.

#include "lesson/lesson.h"

#include "microsim/assessment/scoring/rubric.h"
#include "microsim/assessment/scoring/score.h"
#include "microsim/assessment/storage/history_database.h"
#include "microsim/sim/scene/input_frame.h"
#include "microsim/sim/mesh/vessel.h"
#include "microsim/sim/scene/scene_events.h"

#include <QWidget>

#include <memory>
#include <thread>
#include <vector>

class QLabel;
class QListWidget;
class QPushButton;
class QTimer;

namespace microsim::tracking {
class ManualSource;
}

namespace microsim::gui {

class SimulationRunner;
class Viewport;

struct AttemptResult {
  int lessonIndex = -1;
  assessment::AttemptMode mode = assessment::AttemptMode::Learn;
  qint64 attemptId = 0;       ///< 0 when the history is unavailable
  bool scored = false;        ///< false: `error` says why
  bool stored = false;        ///< the score reached the history
  QString error;              ///< translated
  assessment::AttemptScore score;
  std::vector<sim::PierceEvent> pierces;  ///< as the graded replay saw them
  std::vector<sim::VesselDef> vessels;    ///< the scene's vessels, for drawing the pierces
  QString recordingPath;
};

class AttemptPage : public QWidget {
  Q_OBJECT

 public:
  AttemptPage(assessment::HistoryDatabase* history, QWidget* parent = nullptr);
  ~AttemptPage() override;

  /// Prepares an attempt; false with a translated `error` when the scene or rubric fails.
  bool begin(const lesson::Lesson& lesson, int lessonIndex, assessment::AttemptMode mode,
             const assessment::Viewer& viewer, const QString& language, QString* error);
  void startLive();
  /// `finishAtEnd`: finish (score) when the frames are done; else the attempt stays open.
  void replay(std::vector<sim::InputFrame> frames, bool finishAtEnd = true);
  /// Applies the view settings (stereo mode) to the viewport now.
  void applyViewSettings();
  void finish();
  void abandon();

  bool isActive() const { return active_; }
  qint64 attemptId() const { return attemptId_; }
  int stepsDone() const { return stepsDone_; }
  Viewport* viewport() const { return viewport_; }
  SimulationRunner* runner() const { return runner_.get(); }

  /// Applies the key-map setting to keys for the tool source (AZERTY letters → the map's).
  static int mapKey(int key, const QString& keyMap);

 Q_SIGNALS:
  void finished(const microsim::gui::AttemptResult& result);
  void abandoned();

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  void updateProgress();
  /// Says so on the page when a forceps closed on nothing; the next grasp clears it.
  void noteGrasps(const std::vector<sim::SceneEvent>& events);
  void stopRunning();
  void scored(const AttemptResult& result);

  assessment::HistoryDatabase* history_;
  std::unique_ptr<SimulationRunner> runner_;
  tracking::ManualSource* manual_ = nullptr;
  Viewport* viewport_ = nullptr;
  QLabel* title_ = nullptr;
  QLabel* mode_ = nullptr;
  QListWidget* steps_ = nullptr;
  QLabel* status_ = nullptr;
  QPushButton* finish_ = nullptr;
  QPushButton* abandon_ = nullptr;
  QTimer* progressTimer_ = nullptr;
  std::thread scoring_;  // replays and scores the finished attempt

  lesson::Lesson lesson_;
  int lessonIndex_ = -1;
  assessment::AttemptMode attemptMode_ = assessment::AttemptMode::Learn;
  assessment::Rubric rubric_;
  QString scenePath_;
  QString recordingPath_;
  QString language_;
  qint64 attemptId_ = 0;
  bool active_ = false;
  bool replaying_ = false;
  bool finishAtEnd_ = true;
  int stepsDone_ = 0;
  std::size_t eventsSeen_ = 0;  ///< the scene's events noteGrasps has looked at
  bool graspNoted_ = false;     ///< the status shows a grasp that closed on nothing
  std::vector<float> restPositions_;
  double maxDisplacementMm_ = 0.0;
};

}  // namespace microsim::gui

Q_DECLARE_METATYPE(microsim::gui::AttemptResult)
