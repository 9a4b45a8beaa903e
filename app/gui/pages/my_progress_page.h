#pragma once
// "My progress": a trainee's own history, read-only. Per lesson, the score over their
// finished attempts with the pass mark and the key metrics with their target bands (the
// review's TraineeHistoryView, the instructor's view of a trainee), the attempts, and for the
// chosen attempt its metrics with feedback, the never-events, the pierces, the notes
// instructors wrote on it and its replay (the review's AttemptDetailView, without the note
// editor). The newest attempt is shown when a lesson opens.
//
// The history is read on a loader thread with its own connection (trainee_progress_loader.h);
// the storage layer gives a trainee only their own attempts.

#include "gui/pages/trainee_progress_loader.h"
#include "lesson/lesson.h"

#include <QWidget>

#include <memory>
#include <vector>

class QComboBox;
class QLabel;
class QTabWidget;

namespace microsim::gui {

class AttemptDetailView;
class TraineeHistoryView;

class MyProgressPage : public QWidget {
  Q_OBJECT

 public:
  /// `historyLocation`: the history to read (HistoryDatabase::location()); empty: none.
  explicit MyProgressPage(QString historyLocation, QWidget* parent = nullptr);
  ~MyProgressPage() override;

  /// Shows `viewer`'s history (their `name`) in `lessonId` (empty or unknown: the first
  /// lesson) among `lessons`, titles in `language`.
  void open(const std::vector<lesson::Lesson>& lessons, const assessment::Viewer& viewer, const QString& name,
            const QString& lessonId, const QString& language);
  /// The lesson shown.
  QString lessonId() const;

  QComboBox* lessonChooser() const { return lessonCombo_; }
  QTabWidget* tabs() const { return tabs_; }
  TraineeHistoryView* historyView() const { return historyView_; }
  AttemptDetailView* detailView() const { return detailView_; }
  /// The line above the tabs: loading, a read error, or how many attempts carry notes.
  QString message() const;

 Q_SIGNALS:
  void back();
  /// The shown lesson's history has arrived and is on screen.
  void loaded();

 private:
  void loadLesson();
  void showProgress(const TraineeProgress& progress);
  void showAttempt(qint64 attemptId);
  const lesson::Lesson* shownLesson() const;

  std::unique_ptr<TraineeProgressLoader> loader_;
  std::vector<lesson::Lesson> lessons_;
  assessment::Viewer viewer_;
  QString name_;
  QString language_;
  TraineeProgress progress_;

  QComboBox* lessonCombo_ = nullptr;
  QLabel* message_ = nullptr;
  QTabWidget* tabs_ = nullptr;
  TraineeHistoryView* historyView_ = nullptr;
  AttemptDetailView* detailView_ = nullptr;
};

}  // namespace microsim::gui
