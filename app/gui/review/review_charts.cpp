#include "gui/review/review_charts.h"

#include "gui/metric_vocabulary.h"

#include <QAreaSeries>
#include <QChart>
#include <QLineSeries>
#include <QLocale>
#include <QPen>
#include <QValueAxis>

#include <algorithm>
#include <cmath>
#include <limits>

namespace microsim::gui {
namespace {

// an x axis of attempt numbers 1..count with integer ticks
QValueAxis* attemptAxis(int count) {
  auto* axis = new QValueAxis;
  axis->setRange(0.5, std::max(count, 1) + 0.5);
  // "%.0f", not "%d": with localised numbers (localisedChart) Qt 6.4 draws no label at all for
  // "%d" on the axis' real values, and the attempts went unnumbered
  axis->setLabelFormat(QStringLiteral("%.0f"));
  axis->setTickType(QValueAxis::TicksDynamic);
  axis->setTickAnchor(1);
  axis->setTickInterval(std::max(1, (count + 9) / 10));
  return axis;
}

// a chart whose axes write numbers as the interface's locale does ("2,5" in German)
QChart* localisedChart() {
  auto* chart = new QChart;
  chart->setLocale(QLocale());
  chart->setLocalizeNumbers(true);
  return chart;
}

void attach(QChart* chart, QAbstractSeries* series, QValueAxis* x, QValueAxis* y) {
  chart->addSeries(series);
  series->attachAxis(x);
  series->attachAxis(y);
}

}  // namespace

QChart* ReviewCharts::scoreChart(const QList<double>& scores, std::optional<double> passMark) {
  QChart* chart = localisedChart();
  chart->setTitle(tr("Score over attempts"));
  auto* x = attemptAxis(int(scores.size()));
  x->setTitleText(tr("Attempt"));
  auto* y = new QValueAxis;
  y->setRange(0, 100);
  y->setTitleText(tr("Score"));
  chart->addAxis(x, Qt::AlignBottom);
  chart->addAxis(y, Qt::AlignLeft);

  auto* series = new QLineSeries;
  series->setObjectName(QString::fromLatin1(kScoreSeriesName));
  series->setName(tr("Score"));
  series->setPointsVisible(true);
  for (int i = 0; i < scores.size(); ++i) series->append(i + 1, scores[i]);
  attach(chart, series, x, y);

  if (passMark) {
    auto* line = new QLineSeries;
    line->setObjectName(QString::fromLatin1(kPassMarkSeriesName));
    line->setName(tr("Pass mark"));
    line->append(x->min(), *passMark);
    line->append(x->max(), *passMark);
    QPen pen(Qt::darkGreen);
    pen.setStyle(Qt::DashLine);
    pen.setWidthF(1.5);
    line->setPen(pen);
    attach(chart, line, x, y);
  }
  return chart;
}

QChart* ReviewCharts::metricChart(const QString& title, const QString& unit, const QList<QPointF>& points,
                                  std::optional<TargetBand> band, int attemptCount) {
  QChart* chart = localisedChart();
  const QString symbol = MetricVocabulary::unitSymbol(unit.toStdString());
  chart->setTitle(symbol.isEmpty() ? title : tr("%1 (%2)").arg(title, symbol));
  chart->legend()->hide();
  auto* x = attemptAxis(attemptCount);
  auto* y = new QValueAxis;
  chart->addAxis(x, Qt::AlignBottom);
  chart->addAxis(y, Qt::AlignLeft);

  // the y range holds every value and the band's finite ends, with a margin
  double low = std::numeric_limits<double>::infinity();
  double high = -low;
  const auto include = [&low, &high](double v) {
    if (!std::isfinite(v)) return;
    low = std::min(low, v);
    high = std::max(high, v);
  };
  for (const QPointF& p : points) include(p.y());
  if (band) {
    include(band->low);
    include(band->high);
  }
  if (low > high) {  // nothing to show: a unit range
    low = 0.0;
    high = 1.0;
  }
  const double margin = std::max(0.1 * (high - low), 1e-3 + 0.05 * std::abs(high));
  // a quantity that is never negative here (a time, an angle's size, a count) keeps its axis
  // at or above zero: "-3.1 s" under a row of times reads as a fault; the ticks are made round
  y->setRange(low >= 0.0 ? std::max(0.0, low - margin) : low - margin, high + margin);
  y->applyNiceNumbers();
  if (low >= 0.0 && y->min() < 0.0) y->setMin(0.0);

  if (band) {
    // an open end (the side that is never bad) runs to the edge of the chart
    const double bandLow = std::max(band->low, y->min());
    const double bandHigh = std::min(band->high, y->max());
    auto* upper = new QLineSeries;
    auto* lower = new QLineSeries;
    upper->append(x->min(), bandHigh);
    upper->append(x->max(), bandHigh);
    lower->append(x->min(), bandLow);
    lower->append(x->max(), bandLow);
    auto* area = new QAreaSeries(upper, lower);
    area->setObjectName(QString::fromLatin1(kTargetBandSeriesName));
    area->setName(tr("Target"));
    area->setColor(QColor(120, 200, 120, 90));
    area->setBorderColor(QColor(80, 160, 80));
    attach(chart, area, x, y);
  }
  auto* series = new QLineSeries;
  series->setObjectName(QString::fromLatin1(kMetricSeriesName));
  series->setName(title);
  series->setPointsVisible(true);
  for (const QPointF& p : points) series->append(p);
  attach(chart, series, x, y);
  return chart;
}

QLineSeries* ReviewCharts::scoreSeries(QChart* chart) {
  if (!chart) return nullptr;
  for (QAbstractSeries* s : chart->series()) {
    if (s->objectName() == QLatin1String(kScoreSeriesName)) return qobject_cast<QLineSeries*>(s);
  }
  return nullptr;
}

}  // namespace microsim::gui
