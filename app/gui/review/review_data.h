#pragma once
// What the review screens show, computed from what the history hands out: no SQL here and
// no widgets. The page asks the history's stores with the signed-in Viewer (the storage layer
// decides what that viewer may see) and passes the rows to these functions.
//
// Grid cell of one trainee and one lesson:
//   attempts   every attempt (in progress, interrupted and abandoned included);
//   abandoned  those the trainee gave up on (confirmed), never scored;
//   best       the highest stored score of the finished ones;
//   status     the trainee's standing in the lesson, from the one function the trainee's
//              lesson list asks too (gui/pages/lesson_status.h): passed, proficient, ...
// Target band of a metric (units of the rubric): the values with full points, i.e.
//   bad side "above": [target, target + tolerance]; "below": [target − tolerance, target];
//   "both": [target − tolerance, target + tolerance].

#include "gui/pages/lesson_status.h"
#include "gui/pages/opened_vessel_image.h"
#include "microsim/assessment/scoring/rubric.h"
#include "microsim/assessment/storage/history_types.h"

#include <QHash>
#include <QList>
#include <QString>
#include <QStringList>

#include <map>
#include <optional>
#include <vector>

namespace microsim::gui {

/// A lesson as the review needs it: its id, title and the files it names.
struct ReviewLesson {
  QString id;
  QString title;       ///< in the UI language, the id when no lesson file is known
  QString scenePath;   ///< absolute; empty when no lesson file names this id
  QString rubricPath;  ///< absolute; empty when unknown
};

/// The shipped lessons and their rubrics, loaded once.
class ReviewCatalog {
 public:
  /// Reads every lesson in `lessonsDirectory` and the rubric each names.
  explicit ReviewCatalog(const QString& lessonsDirectory);
  /// Lessons by file order, then ids seen only in `attempts` (sorted).
  QList<ReviewLesson> lessons(const QList<assessment::AttemptSummary>& attempts) const;
  /// The lesson with this id, or null.
  const ReviewLesson* lesson(const QString& id) const;
  /// The rubric of a lesson, or null when it has none or it does not load.
  const assessment::Rubric* rubric(const QString& lessonId) const;

 private:
  std::vector<ReviewLesson> lessons_;
  std::map<QString, assessment::Rubric> rubrics_;
};

struct GridCell {
  int attempts = 0;
  int finished = 0;
  int abandoned = 0;
  std::optional<double> best;  ///< 0..100
  LessonStatus status = LessonStatus::NotStarted;
};

struct GridRow {
  assessment::Trainee trainee;
  QHash<QString, GridCell> cells;  ///< by lesson id; absent: no attempt
};

/// One row per person in `people` whose group is `group` (empty: every group), in the
/// order given; `attempts` may hold anyone's (others are ignored).
std::vector<GridRow> buildGrid(const QList<assessment::Trainee>& people,
                               const QList<assessment::AttemptSummary>& attempts,
                               const ReviewCatalog& catalog, const QString& group = {});

/// The finished attempts of one trainee in one lesson (empty lesson: every lesson), oldest
/// first: what the history charts plot, one point each.
QList<assessment::AttemptSummary> finishedAttempts(const QList<assessment::AttemptSummary>& attempts,
                                                   qint64 traineeId, const QString& lesson = {});

/// The values that score full points. A metric whose only bad side is "too high" (time, path)
/// has no lower end (low = −∞), one whose only bad side is "too low" no upper end (high = +∞).
struct TargetBand {
  double low = 0;
  double high = 0;

  bool contains(double value) const { return value >= low && value <= high; }
};

/// The band of full points of `key` in `rubric`, open on the side that is never bad; nullopt
/// when the rubric does not weigh it.
std::optional<TargetBand> targetBand(const assessment::Rubric& rubric, const QString& key);

/// The metrics the history charts follow, in display order.
QStringList keyMetrics();

/// The stored value of `key` in `metrics`; nullopt when absent or NaN.
std::optional<double> metricValue(const QList<assessment::StoredMetric>& metrics, const QString& key);

/// One pierce's stored values by key ("entry_angle_deg", "bite_mm", ...).
struct PierceRow {
  int pierce = 0;
  QHash<QString, double> values;  ///< NaN when stored as NULL
};

/// Groups the stored per-pierce values by pierce, in pierce order.
std::vector<PierceRow> pierceRows(const QList<assessment::StoredPierceValue>& values);

/// A stored attempt's opened vessel: its passages from the stored pierce values, their
/// stitches as the scorer paired them (stitchMetrics), and its stored end-product errors.
OpenedVessel openedVessel(const assessment::AttemptDetail& detail);

}  // namespace microsim::gui
