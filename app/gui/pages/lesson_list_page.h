#pragma once
// The lessons for the signed-in person: title, goals, and their status in each (lesson_status.h),
// with Learn (guided) and Test (graded, no hints) buttons, and "My progress" (their own
// history, my_progress_page.h) for a person whose attempts are stored.

#include "gui/pages/lesson_status.h"
#include "lesson/lesson.h"

#include "microsim/assessment/storage/history_database.h"

#include <QWidget>

#include <vector>

class QLabel;
class QTableWidget;
class QPushButton;

namespace microsim::gui {

class LessonListPage : public QWidget {
  Q_OBJECT

 public:
  LessonListPage(assessment::HistoryDatabase* history, QWidget* parent = nullptr);

  /// Shows `lessons` for `viewer`, in `language`.
  void show(const std::vector<lesson::Lesson>& lessons, const assessment::Viewer& viewer,
            const QString& name, const QString& language);
  /// The status shown in row `row` (for tests).
  LessonStatus status(int row) const { return statuses_.at(static_cast<std::size_t>(row)); }
  /// The word shown in row `row`'s status column.
  QString statusText(int row) const;
  int selectedRow() const;
  void selectRow(int row);

 Q_SIGNALS:
  void startLesson(int index, microsim::assessment::AttemptMode mode);
  void signOut();
  /// "My progress", opened on `lessonId` (the selected lesson; empty: none selected).
  void showProgress(const QString& lessonId);

 private:
  void showGoals();
  void start(assessment::AttemptMode mode);

  assessment::HistoryDatabase* history_;
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
