#pragma once
// The review's files: the CSV export (assessment::exportAttemptsCsv, RFC 4180, exactly the
// attempts the viewer may see) and a trainee's PDF report (QPdfWriter, A4): a header with
// name, group and date, the table of every attempt, per lesson the score chart with its
// pass mark, drawn as vectors, and, on a page of their own, the attempts whose finished
// anastomosis has errors: each opened with its errors marked (opened_vessel_image.h) and
// listed as the attempt view lists them (end_product_panel.h).

#include "gui/review/review_data.h"
#include "microsim/assessment/storage/history_database.h"

#include <QCoreApplication>
#include <QHash>
#include <QList>
#include <QString>

namespace microsim::gui {

struct TraineeReport {
  assessment::Trainee trainee;
  QList<assessment::AttemptSummary> attempts;  ///< the trainee's, oldest first
  /// by attempt id, the opened vessel of each attempt with end-product errors
  QHash<qint64, OpenedVessel> endProducts;
};

class ReviewReport {
  Q_DECLARE_TR_FUNCTIONS(microsim::gui::ReviewReport)

 public:
  /// Writes the CSV to `path` (replacing it); on failure `error` says why, for the user.
  static bool writeCsv(assessment::HistoryDatabase& history, const assessment::Viewer& viewer,
                       const QString& path, QString* error);
  /// Writes the PDF report to `path`; on failure `error` says why, for the user.
  static bool writePdf(const TraineeReport& report, const ReviewCatalog& catalog, const QString& path,
                       QString* error);
};

}  // namespace microsim::gui
