#pragma once
// The history's charts (Qt Charts): a trainee's score over their finished attempts with the
// rubric's pass mark as a line, and one key metric over the same attempts with the rubric's
// band of full points (review_data.h) shaded behind it. x is the attempt's number, 1-based,
// oldest first; each finished attempt is one point.

#include "gui/review/review_data.h"

#include <QCoreApplication>
#include <QList>
#include <QPointF>
#include <QString>

#include <optional>

class QChart;
class QLineSeries;

namespace microsim::gui {

/// Object names of the series, for tests and styling.
inline constexpr char kScoreSeriesName[] = "scoreSeries";
inline constexpr char kPassMarkSeriesName[] = "passMarkSeries";
inline constexpr char kMetricSeriesName[] = "metricSeries";
inline constexpr char kTargetBandSeriesName[] = "targetBandSeries";

class ReviewCharts {
  Q_DECLARE_TR_FUNCTIONS(microsim::gui::ReviewCharts)

 public:
  /// Score (0..100) per attempt; `passMark` draws a horizontal line. The caller owns it.
  static QChart* scoreChart(const QList<double>& scores, std::optional<double> passMark);

  /// `points` are (attempt number, value in `unit`); `band` shades the values with full
  /// points, an open end up to the chart's edge. The caller owns the chart.
  static QChart* metricChart(const QString& title, const QString& unit, const QList<QPointF>& points,
                             std::optional<TargetBand> band, int attemptCount);

  /// The series named kScoreSeriesName of `chart`, or null.
  static QLineSeries* scoreSeries(QChart* chart);
};

}  // namespace microsim::gui
