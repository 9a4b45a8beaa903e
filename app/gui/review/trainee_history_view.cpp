#include "gui/review/trainee_history_view.h"

#include "gui/metric_vocabulary.h"
#include "gui/review/review_charts.h"
#include "gui/review/review_text.h"

#include <QChart>
#include <QChartView>
#include <QGridLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QScrollArea>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>

namespace microsim::gui {
namespace {

// puts `chart` into `view`, deleting the chart it showed before
void replaceChart(QChartView* view, QChart* chart) {
  QChart* old = view->chart();
  view->setChart(chart);
  delete old;
}

QChartView* makeView() {
  auto* view = new QChartView;
  view->setRenderHint(QPainter::Antialiasing);
  view->setMinimumSize(260, 200);
  return view;
}

QTableWidgetItem* item(const QString& text, qint64 attemptId) {
  auto* it = new QTableWidgetItem(text);
  it->setData(Qt::UserRole, attemptId);
  it->setFlags(it->flags() & ~Qt::ItemIsEditable);
  return it;
}

}  // namespace

TraineeHistoryView::TraineeHistoryView(QWidget* parent) : QWidget(parent) {
  scoreView_ = makeView();
  // the score chart keeps room for its title, legend and numbered axis however many metric
  // charts follow (squeezed to a third of the instructor's page, its labels were elided to "…")
  scoreView_->setMinimumHeight(320);
  auto* charts = new QWidget;
  chartGrid_ = new QGridLayout(charts);
  chartGrid_->setContentsMargins(0, 0, 0, 0);
  chartGrid_->addWidget(scoreView_, 0, 0, 1, 2);

  table_ = new QTableWidget(0, 5);
  table_->setHorizontalHeaderLabels({tr("Attempt"), tr("Finished"), tr("Mode"), tr("Score"), tr("Passed")});
  table_->horizontalHeader()->setStretchLastSection(true);
  table_->verticalHeader()->hide();
  // three attempts stay readable under the charts however the splitter shares the height
  table_->setMinimumHeight(table_->horizontalHeader()->sizeHint().height() +
                           3 * table_->verticalHeader()->defaultSectionSize() +
                           2 * table_->frameWidth());
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setSelectionMode(QAbstractItemView::SingleSelection);
  connect(table_, &QTableWidget::cellActivated, this, [this](int row, int) {
    Q_EMIT attemptChosen(table_->item(row, 0)->data(Qt::UserRole).toLongLong());
  });

  emptyLabel_ = new QLabel(tr("No finished attempts in this lesson yet."));
  emptyLabel_->setAlignment(Qt::AlignCenter);

  // the charts need more height than a page has: they scroll above the attempts, which stay
  auto* chartScroll = new QScrollArea;
  chartScroll->setWidgetResizable(true);
  chartScroll->setFrameShape(QFrame::NoFrame);
  chartScroll->setWidget(charts);
  auto* splitter = new QSplitter(Qt::Vertical);
  splitter->addWidget(chartScroll);
  splitter->addWidget(table_);
  splitter->setStretchFactor(0, 3);
  splitter->setStretchFactor(1, 1);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(emptyLabel_);
  layout->addWidget(splitter, 1);
  setHistory({}, {}, nullptr);
}

void TraineeHistoryView::setHistory(const QList<assessment::AttemptSummary>& finished,
                                    const QList<QList<assessment::StoredMetric>>& metrics,
                                    const assessment::Rubric* rubric) {
  emptyLabel_->setVisible(finished.isEmpty());
  const int count = int(finished.size());

  QList<double> scores;
  for (const assessment::AttemptSummary& a : finished) scores << a.score.value_or(0.0);
  replaceChart(scoreView_, ReviewCharts::scoreChart(
                               scores, rubric ? std::optional<double>(rubric->passMark) : std::nullopt));

  // one chart per key metric measured in these attempts: its stored value in each that has
  // it (a metric the lesson never measures would only be an empty chart)
  qDeleteAll(metricViews_);
  metricViews_.clear();
  for (const QString& key : keyMetrics()) {
    QList<QPointF> points;
    for (int i = 0; i < count && i < metrics.size(); ++i) {
      if (auto v = metricValue(metrics[i], key)) points << QPointF(i + 1, *v);
    }
    if (points.isEmpty()) continue;
    const std::optional<TargetBand> band = rubric ? targetBand(*rubric, key) : std::nullopt;
    QChart* chart = ReviewCharts::metricChart(MetricVocabulary::metricLabel(key), MetricVocabulary::metricUnit(key),
                                              points, band, count);
    chart->setObjectName(key);
    QChartView* view = makeView();
    replaceChart(view, chart);
    const int slot = int(metricViews_.size());
    chartGrid_->addWidget(view, 1 + slot / 2, slot % 2);
    metricViews_ << view;
  }

  // newest first in the table, as an instructor reads it
  table_->setRowCount(count);
  const QLocale locale;
  for (int i = 0; i < count; ++i) {
    const assessment::AttemptSummary& a = finished[count - 1 - i];
    table_->setItem(i, 0, item(QString::number(count - i), a.id));
    table_->setItem(i, 1, item(locale.toString(a.finished.toLocalTime(), QLocale::ShortFormat), a.id));
    table_->setItem(i, 2, item(ReviewText::mode(a.mode), a.id));
    table_->setItem(i, 3, item(locale.toString(a.score.value_or(0.0), 'f', 1), a.id));
    table_->setItem(i, 4, item(a.passed ? tr("yes") : tr("no"), a.id));
  }
  // a date on one line, not wrapped in a column sized for a number
  for (int column = 0; column + 1 < table_->columnCount(); ++column)
    table_->resizeColumnToContents(column);
}

QChart* TraineeHistoryView::scoreChart() const { return scoreView_->chart(); }

QList<QChart*> TraineeHistoryView::metricCharts() const {
  QList<QChart*> charts;
  for (QChartView* v : metricViews_) charts << v->chart();
  return charts;
}

}  // namespace microsim::gui
