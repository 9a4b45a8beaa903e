#include "gui/review/trainee_history_view.h"

#include "gui/review/review_charts.h"
#include "gui/review/review_text.h"
#include "microsim/assessment/scoring/metrics.h"

#include <QChart>
#include <QChartView>
#include <QGridLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
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
  auto* charts = new QWidget;
  auto* grid = new QGridLayout(charts);
  grid->setContentsMargins(0, 0, 0, 0);
  grid->addWidget(scoreView_, 0, 0, 1, 2);
  const QStringList keys = keyMetrics();
  for (int i = 0; i < keys.size(); ++i) {
    QChartView* view = makeView();
    metricViews_ << view;
    grid->addWidget(view, 1 + i / 2, i % 2);
  }

  table_ = new QTableWidget(0, 5);
  table_->setHorizontalHeaderLabels({tr("Attempt"), tr("Finished"), tr("Mode"), tr("Score"), tr("Passed")});
  table_->horizontalHeader()->setStretchLastSection(true);
  table_->verticalHeader()->hide();
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setSelectionMode(QAbstractItemView::SingleSelection);
  connect(table_, &QTableWidget::cellActivated, this, [this](int row, int) {
    Q_EMIT attemptChosen(table_->item(row, 0)->data(Qt::UserRole).toLongLong());
  });

  emptyLabel_ = new QLabel(tr("No finished attempts in this lesson yet."));
  emptyLabel_->setAlignment(Qt::AlignCenter);

  auto* splitter = new QSplitter(Qt::Vertical);
  splitter->addWidget(charts);
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

  // one chart per key metric: its stored value in each attempt that has it
  const QStringList keys = keyMetrics();
  for (int k = 0; k < keys.size(); ++k) {
    QList<QPointF> points;
    for (int i = 0; i < count && i < metrics.size(); ++i) {
      if (auto v = metricValue(metrics[i], keys[k])) points << QPointF(i + 1, *v);
    }
    const assessment::MetricInfo* info = assessment::findMetric(keys[k].toStdString());
    const QString unit = info ? QString::fromUtf8(info->unit.data(), qsizetype(info->unit.size())) : QString();
    const std::optional<TargetBand> band = rubric ? targetBand(*rubric, keys[k]) : std::nullopt;
    QString title = ReviewText::metricName(keys[k]);
    if (points.isEmpty()) title = tr("%1 — not measured in this lesson").arg(title);
    replaceChart(metricViews_[k], ReviewCharts::metricChart(title, unit, points, band, count));
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
}

QChart* TraineeHistoryView::scoreChart() const { return scoreView_->chart(); }

QList<QChart*> TraineeHistoryView::metricCharts() const {
  QList<QChart*> charts;
  for (QChartView* v : metricViews_) charts << v->chart();
  return charts;
}

}  // namespace microsim::gui
