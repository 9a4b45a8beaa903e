#pragma once
// One attempt at a lesson, as the trainee sees it: the microscope viewport on the lesson's
// scene, the steps with a tick as each success condition is met (lesson/progress.h), and in
// Learn mode the lesson's guides (target rings and ideal needle directions; none in Test
// mode). The page only shows: the attempt itself — scene, recording, progress, scoring and
// every history write — is an AttemptSession (session/attempt_session.h), one per begin().
//
//   Finish attempt  scores and stores it; finished follows with the result.
//   Abandon         asks first (a QMessageBox, object name "abandonConfirmation"); confirmed,
//                   the attempt is stored as abandoned and abandoned follows.
//   stop()          (leaving the page, closing the window) ends the run without a verdict:
//                   the history marks the attempt interrupted when it is next opened.
//
// When the scissors cut the thread the page says so under the steps (object name
// "attemptCut": the latest cut's cut-end length in the locale's format), and once a cut has
// left the needle too little thread to tie, a warning stays ("attemptThreadTooShort").

#include "gui/session/attempt_result.h"
#include "lesson/lesson.h"

#include "microsim/assessment/storage/history_database.h"
#include "microsim/sim/scene/input_frame.h"

#include <QWidget>

#include <memory>
#include <vector>

class QLabel;
class QListWidget;
class QPushButton;

namespace microsim::tracking {
class ManualSource;
}

namespace microsim::gui {

class AttemptSession;
struct AttemptProgress;
class SimulationRunner;
class Viewport;

class AttemptPage : public QWidget {
  Q_OBJECT

 public:
  /// `history` (may be closed or null): where attempts are stored, through a connection of
  /// each attempt's own on its worker thread.
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
  /// Asks for confirmation, then abandons (what the Abandon button does).
  void confirmAbandon();
  /// Ends the run without a verdict (see above).
  void stop();

  bool isActive() const;
  /// 0 until the history has begun the attempt, and when it is not stored.
  qint64 attemptId() const;
  int stepsDone() const;
  Viewport* viewport() const { return viewport_; }
  /// The keyboard and mouse source (its working volume fits the attempt's scene).
  const tracking::ManualSource* manualSource() const { return manual_; }
  /// The running attempt's simulation; null before the first begin().
  SimulationRunner* runner() const;
  AttemptSession* session() const { return session_.get(); }

  /// Applies the key-map setting to keys for the tool source (AZERTY letters → the map's).
  static int mapKey(int key, const QString& keyMap);
  /// A sentence for what went wrong.
  static QString describe(const AttemptProblem& problem);

 Q_SIGNALS:
  void finished(const microsim::gui::AttemptResult& result);
  void abandoned();

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  void showProgress(const AttemptProgress& progress);
  void showCuts(const AttemptProgress& progress);
  void closeSession();

  assessment::HistoryDatabase* history_;
  std::unique_ptr<AttemptSession> session_;
  tracking::ManualSource* manual_ = nullptr;
  Viewport* viewport_ = nullptr;
  QLabel* title_ = nullptr;
  QLabel* mode_ = nullptr;
  QListWidget* steps_ = nullptr;
  QLabel* status_ = nullptr;
  QLabel* cut_ = nullptr;
  QLabel* tooShort_ = nullptr;
  QPushButton* finish_ = nullptr;
  QPushButton* abandon_ = nullptr;

  lesson::Lesson lesson_;
  QString language_;
  bool replaying_ = false;
  bool graspNoted_ = false;  ///< the status says a grasp closed on nothing
};

}  // namespace microsim::gui
