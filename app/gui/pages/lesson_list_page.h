#pragma once
// The lessons for the signed-in person: title, goals, and their status in each (lesson_status.h),
// with Learn (guided) and Test (graded, no hints) buttons, and "My progress" (their own
// history, my_progress_page.h) for a person whose attempts are stored.
//
// The attempts the statuses come from are read off the GUI thread (history_reader.h); the
// lessons show at once, their statuses when the read arrives (statusesShown).

#include "gui/pages/history_reader.h"
#include "gui/pages/lesson_status.h"
#include "lesson/lesson.h"

#include "microsim/assessment/storage/history_database.h"

#include <QList>

#include <QWidget>

#include <vector>

class QLabel;
class QTableWidget;
class QPushButton;

namespace microsim::gui {

class LessonListPage : public QWidget {
  Q_OBJECT

 public:
  /// `historyLocation`: the history to read (HistoryDatabase::location()); empty: none.
  explicit LessonListPage(const QString& historyLocation, QWidget* parent = nullptr);

  /// Shows `lessons` for `viewer`, in `language`; their statuses follow.
  void show(const std::vector<lesson::Lesson>& lessons, const assessment::Viewer& viewer,
            const QString& name, const QString& language);
  /// The status shown in row `row` (for tests); NotStarted until statusesLoaded().
  LessonStatus status(int row) const { return statuses_.at(static_cast<std::size_t>(row)); }
  /// True once the statuses of the last show() are on screen.
  bool statusesLoaded() const { return statusesLoaded_; }
  /// The word shown in row `row`'s status column.
  QString statusText(int row) const;
  int selectedRow() const;
  void selectRow(int row);

 Q_SIGNALS:
  void startLesson(int index, microsim::assessment::AttemptMode mode);
  void signOut();
  /// "My progress", opened on `lessonId` (the selected lesson; empty: none selected).
  void showProgress(const QString& lessonId);
  /// The statuses of the last show() are on screen.
  void statusesShown();

 private:
  void showGoals();
  void start(assessment::AttemptMode mode);
  // the statuses from `attempts` (a failed read: `error`, and no statuses)
  void showStatuses(const QList<assessment::AttemptSummary>& attempts, qint64 userId, const QString& error);

  HistoryReader* reader_ = nullptr;  // null: no history
  bool statusesLoaded_ = false;
  std::vector<lesson::Lesson> lessons_;
  std::vector<LessonStatus> statuses_;
  QString language_;
  QLabel* heading_ = nullptr;
  QTableWidget* table_ = nullptr;
  QLabel* goals_ = nullptr;
  QPushButton* learn_ = nullptr;
  QPushButton* test_ = nullptr;
  QPushButton* progress_ = nullptr;
};

}  // namespace microsim::gui
