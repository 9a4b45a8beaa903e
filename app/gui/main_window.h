#pragma once
// The main window: a stack of pages — sign-in, the lesson list, an attempt (the microscope
// viewport with the lesson's steps), and its results — with menus (settings, language, the
// microscope's named views and the key and mouse map) and a status bar that says where the trainee history is kept (or why it could
// not be opened).
//
// Closing the window during an attempt stops the simulation and leaves the attempt unfinished
// in the history (in progress, marked interrupted when the history is next opened); its
// recording file keeps every frame up to the close. Abandoning one (confirmed) stores it as
// abandoned.

#include "gui/pages/attempt_page.h"
#include "lesson/lesson.h"

#include "microsim/assessment/storage/history_database.h"

#include <QMainWindow>

#include <vector>

class QLabel;
class QStackedWidget;

namespace microsim::gui {

class CalibrationSession;
class LessonListPage;
class ReviewPage;
class ResultsPage;
class SignInPage;
class Viewport;

class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  /// `history` may be closed (unusable); it must outlive the window.
  MainWindow(assessment::HistoryDatabase* history, const assessment::DatabaseStatus& database,
             const QString& databasePath, QWidget* parent = nullptr);
  ~MainWindow() override;

  /// The attempt page's microscope viewport.
  Viewport* viewport() const;
  SignInPage* signInPage() const { return signIn_; }
  LessonListPage* lessonListPage() const { return lessonList_; }
  AttemptPage* attemptPage() const { return attempt_; }
  ResultsPage* resultsPage() const { return results_; }
  /// The instructor's review, while an instructor is signed in; null otherwise.
  ReviewPage* reviewPage() const { return review_; }
  CalibrationSession* calibration() const { return calibration_; }
  QWidget* currentPage() const;
  const std::vector<lesson::Lesson>& lessons() const { return lessons_; }
  /// The status bar's text about the history database.
  QString databaseMessage() const;

  /// Starts lesson `index` in `mode` for the signed-in person (what the lesson list's buttons do).
  bool startLesson(int index, assessment::AttemptMode mode);
  /// Opens the settings dialog; applies what was accepted.
  void openSettings();

  /// A user-readable sentence for a database status.
  static QString describe(const assessment::DatabaseStatus& status, const QString& path);

 protected:
  void closeEvent(QCloseEvent* event) override;

 private:
  void buildMenus();
  void showLessons();
  void showResults(const AttemptResult& result);
  void replayRecording();
  void showAbout();
  QString language() const;

  void showReview();
  void signOut();

  assessment::HistoryDatabase* history_;
  ReviewPage* review_ = nullptr;
  CalibrationSession* calibration_ = nullptr;
  QStackedWidget* pages_ = nullptr;
  SignInPage* signIn_ = nullptr;
  LessonListPage* lessonList_ = nullptr;
  AttemptPage* attempt_ = nullptr;
  ResultsPage* results_ = nullptr;
  QLabel* databaseLabel_ = nullptr;
  QLabel* userLabel_ = nullptr;

  std::vector<lesson::Lesson> lessons_;
  assessment::Viewer viewer_;
  QString userName_;
  int lastLesson_ = -1;
  assessment::AttemptMode lastMode_ = assessment::AttemptMode::Learn;
};

}  // namespace microsim::gui
