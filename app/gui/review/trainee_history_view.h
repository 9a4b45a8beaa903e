#pragma once
// A trainee's history in one lesson: the score chart, the charts of the key metrics measured
// in these attempts with their target bands, and the table of finished attempts (choosing a
// row opens that attempt).

#include "gui/review/review_data.h"

#include <QList>
#include <QWidget>

class QChart;
class QChartView;
class QGridLayout;
class QLabel;
class QTableWidget;

namespace microsim::gui {

class TraineeHistoryView : public QWidget {
  Q_OBJECT

 public:
  explicit TraineeHistoryView(QWidget* parent = nullptr);

  /// Shows `finished` (oldest first, one chart point each) with their stored metrics
  /// (`metrics[i]` belongs to `finished[i]`); `rubric` gives the pass mark and the bands
  /// (null: neither).
  void setHistory(const QList<assessment::AttemptSummary>& finished,
                  const QList<QList<assessment::StoredMetric>>& metrics, const assessment::Rubric* rubric);

  QChart* scoreChart() const;
  /// The charts of the key metrics measured in the shown attempts, in keyMetrics() order;
  /// each chart's object name is its metric key.
  QList<QChart*> metricCharts() const;
  QTableWidget* attemptsTable() const { return table_; }

 Q_SIGNALS:
  void attemptChosen(qint64 attemptId);

 private:
  QChartView* scoreView_ = nullptr;
  QGridLayout* chartGrid_ = nullptr;
  QList<QChartView*> metricViews_;
  QTableWidget* table_ = nullptr;
  QLabel* emptyLabel_ = nullptr;
};

}  // namespace microsim::gui
