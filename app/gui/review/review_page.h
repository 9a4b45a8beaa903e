#pragma once
// The review screens: what an instructor sees after signing in (and a trainee, of their own
// history). Three tabs:
//   Overview  a trainee × lesson grid: best score, attempts, passed ✓ and proficient ★,
//             filtered by group;
//   History   one trainee in one lesson: score and key-metric charts, the attempts;
//   Attempt   one attempt's metrics, pierces, annotations and 3D replay.
// Everything shown comes from the history's stores, asked with the signed-in Viewer; the
// storage layer decides what that viewer may see (a trainee gets only their own attempts),
// and the page shows exactly that. Export: the CSV of every visible attempt, and the shown
// trainee's PDF report; without a preset path each asks for a file.

#include "gui/review/review_data.h"
#include "microsim/assessment/storage/history_database.h"

#include <QWidget>

#include <memory>

class QComboBox;
class QLabel;
class QPushButton;
class QTabWidget;
class QTableWidget;

namespace microsim::gui {

class AttemptDetailView;
class TraineeHistoryView;

class ReviewPage : public QWidget {
  Q_OBJECT

 public:
  /// `history` must stay open while the page lives; `viewer` is the signed-in person.
  /// Lessons and rubrics come from `lessonsDirectory` (default: the shipped lessons).
  ReviewPage(assessment::HistoryDatabase& history, const assessment::Viewer& viewer,
             QWidget* parent = nullptr);
  ReviewPage(assessment::HistoryDatabase& history, const assessment::Viewer& viewer,
             const QString& lessonsDirectory, QWidget* parent = nullptr);
  ~ReviewPage() override;

  const assessment::Viewer& viewer() const { return viewer_; }
  /// Re-reads people and attempts and rebuilds the grid, keeping the selection.
  void refresh();
  /// The people the grid lists (after the group filter), in row order.
  QList<assessment::Trainee> shownTrainees() const;
  /// Opens a trainee's history (empty lesson: the lesson of their latest attempt).
  void showTrainee(qint64 traineeId, const QString& lesson = {});
  void showAttempt(qint64 attemptId);
  /// Shows only this group's trainees (empty: everyone).
  void setGroupFilter(const QString& group);

  /// Files the exports write to without asking (empty: ask with a file dialog).
  void setCsvPath(const QString& path) { csvPath_ = path; }
  void setPdfPath(const QString& path) { pdfPath_ = path; }
  bool exportCsv();
  /// The report of the trainee shown in History.
  bool exportPdf();
  /// The last message shown to the user (an export's result, a refused annotation).
  QString message() const;

  QTabWidget* tabs() const { return tabs_; }
  QTableWidget* grid() const { return grid_; }
  QComboBox* groupFilter() const { return groupCombo_; }
  QComboBox* traineeChooser() const { return traineeCombo_; }
  QComboBox* lessonChooser() const { return lessonCombo_; }
  TraineeHistoryView* historyView() const { return historyView_; }
  AttemptDetailView* detailView() const { return detailView_; }

 Q_SIGNALS:
  void signOutRequested();

 private:
  void buildGrid();
  void showHistory();
  void annotate(qint64 attemptId, const QString& note);
  void say(const QString& text, bool error = false);
  QString personName(qint64 id) const;
  const assessment::Trainee* shownTrainee() const;

  assessment::HistoryDatabase& history_;
  assessment::Viewer viewer_;
  std::unique_ptr<ReviewCatalog> catalog_;
  QList<assessment::Trainee> people_;
  QList<assessment::AttemptSummary> attempts_;
  QList<ReviewLesson> lessons_;
  std::vector<GridRow> rows_;
  QString csvPath_;
  QString pdfPath_;

  QTabWidget* tabs_ = nullptr;
  QTableWidget* grid_ = nullptr;
  QComboBox* groupCombo_ = nullptr;
  QComboBox* traineeCombo_ = nullptr;
  QComboBox* lessonCombo_ = nullptr;
  QLabel* who_ = nullptr;
  QLabel* message_ = nullptr;
  TraineeHistoryView* historyView_ = nullptr;
  AttemptDetailView* detailView_ = nullptr;
};

}  // namespace microsim::gui
