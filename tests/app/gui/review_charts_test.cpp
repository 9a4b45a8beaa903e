// The history's metric charts: the green band is where a metric scores full points, whichever
// side is bad, and a metric the shown attempts never measured gets no chart.
#include "gui/review/review_charts.h"

#include "gui/review/trainee_history_view.h"

#include <QAbstractAxis>
#include <QApplication>
#include <QAreaSeries>
#include <QChart>
#include <QChartView>
#include <QImage>
#include <QLineSeries>
#include <QLocale>
#include <QTableWidget>
#include <QValueAxis>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <utility>

namespace microsim::gui {
namespace {

QAbstractSeries* seriesNamed(QChart* chart, const char* name) {
  for (QAbstractSeries* s : chart->series())
    if (s->objectName() == QLatin1String(name)) return s;
  return nullptr;
}

// the band's lower and upper edge as drawn at x
std::pair<double, double> drawnBandAt(QChart* chart, double x) {
  auto* area = qobject_cast<QAreaSeries*>(seriesNamed(chart, kTargetBandSeriesName));
  EXPECT_NE(area, nullptr);
  if (!area) return {0.0, 0.0};
  const auto edgeAt = [x](const QLineSeries* edge) {
    const QPointF a = edge->at(0);
    const QPointF b = edge->at(edge->count() - 1);
    return a.y() + (b.y() - a.y()) * (x - a.x()) / (b.x() - a.x());
  };
  return {edgeAt(area->lowerSeries()), edgeAt(area->upperSeries())};
}

assessment::Rubric rubricWith(const char* key, double target, double tolerance, assessment::BadSide bad) {
  assessment::Rubric rubric;
  assessment::RubricMetric m;
  m.key = key;
  m.target = target;
  m.tolerance = tolerance;
  m.limit = 2.0 * tolerance;
  m.bad = bad;
  rubric.metrics.push_back(m);
  return rubric;
}

TEST(ReviewCharts, AFastTimeLiesInsideTheBandAndASlowOneOutside) {
  // time: only "too slow" is bad, so 120 s against a 300 ± 60 s target scores full points
  const assessment::Rubric rubric = rubricWith("time", 300.0, 60.0, assessment::BadSide::Above);
  const std::optional<TargetBand> band = targetBand(rubric, QStringLiteral("time"));
  ASSERT_TRUE(band.has_value());
  EXPECT_TRUE(band->contains(120.0));
  EXPECT_TRUE(band->contains(360.0));
  EXPECT_FALSE(band->contains(420.0));

  std::unique_ptr<QChart> chart(ReviewCharts::metricChart(QStringLiteral("Time"), QStringLiteral("s"),
                                                          {QPointF(1, 120.0), QPointF(2, 420.0)}, band, 2));
  const auto [low1, high1] = drawnBandAt(chart.get(), 1.0);
  EXPECT_LE(low1, 120.0);
  EXPECT_GE(high1, 120.0);
  const auto [low2, high2] = drawnBandAt(chart.get(), 2.0);
  EXPECT_GT(420.0, high2);
  EXPECT_DOUBLE_EQ(high2, 360.0);
}

TEST(ReviewCharts, AMetricGoodWhenHighHasTheBandAboveItsTarget) {
  const assessment::Rubric rubric = rubricWith("full_thickness", 0.9, 0.1, assessment::BadSide::Below);
  const std::optional<TargetBand> band = targetBand(rubric, QStringLiteral("full_thickness"));
  ASSERT_TRUE(band.has_value());
  std::unique_ptr<QChart> chart(
      ReviewCharts::metricChart(QStringLiteral("Full-thickness passages"), QStringLiteral("1"),
                                {QPointF(1, 1.0), QPointF(2, 0.5)}, band, 2));
  const auto [low, high] = drawnBandAt(chart.get(), 1.0);
  EXPECT_DOUBLE_EQ(low, 0.8);
  EXPECT_GE(high, 1.0);
  EXPECT_LT(0.5, low);
}

// Two attempts of 5.4 s against a limit of 60 s: the axis runs from 0 (no negative time under
// the points) to past the limit, on round ticks
TEST(ReviewCharts, AnAxisOfValuesThatAreNeverNegativeStartsAtZeroOnRoundTicks) {
  const assessment::Rubric rubric = rubricWith("time", 60.0, 30.0, assessment::BadSide::Above);
  std::unique_ptr<QChart> chart(ReviewCharts::metricChart(
      QStringLiteral("Time"), QStringLiteral("s"), {QPointF(1, 5.4), QPointF(2, 5.4)},
      targetBand(rubric, QStringLiteral("time")), 2));
  const auto* y = qobject_cast<QValueAxis*>(chart->axes(Qt::Vertical).value(0));
  ASSERT_NE(y, nullptr);
  EXPECT_EQ(y->min(), 0.0);
  EXPECT_GE(y->max(), 90.0);
  const double step = (y->max() - y->min()) / (y->tickCount() - 1);
  EXPECT_NEAR(step, std::round(step), 1e-9) << step;

  // a metric that can be negative (smoothness) keeps its negative range
  std::unique_ptr<QChart> smooth(
      ReviewCharts::metricChart(QStringLiteral("Smoothness"), QStringLiteral("1"),
                                {QPointF(1, -14.3), QPointF(2, -8.0)}, std::nullopt, 2));
  const auto* ys = qobject_cast<QValueAxis*>(smooth->axes(Qt::Vertical).value(0));
  ASSERT_NE(ys, nullptr);
  EXPECT_LT(ys->min(), -14.3);
  EXPECT_GT(ys->max(), -8.0);
}

// dark pixels in the strip just under the plot area, where an x axis writes its labels
int darkPixelsUnderThePlot(QChart* chart) {
  QChartView view(chart);
  view.resize(400, 300);
  view.show();
  QApplication::processEvents();
  const QImage image = view.grab().toImage();
  const QRect plot = chart->plotArea().toRect();
  int dark = 0;
  for (int y = plot.bottom() + 3; y <= plot.bottom() + 18 && y < image.height(); ++y)
    for (int x = plot.left(); x <= plot.right(); ++x)
      dark += qGray(image.pixel(x, y)) < 128 ? 1 : 0;
  return dark;
}

// The attempts are numbered under the charts: "1" and "2" written below the plot (with
// localised numbers, Qt 6.4 wrote nothing for the "%d" label format)
TEST(ReviewCharts, TheAttemptsAreNumberedUnderTheCharts) {
  std::unique_ptr<QChart> score(ReviewCharts::scoreChart({40.0, 60.0}, 70.0));
  score->axes(Qt::Horizontal).value(0)->setTitleVisible(false);
  EXPECT_GT(darkPixelsUnderThePlot(score.release()), 10);
  std::unique_ptr<QChart> metric(
      ReviewCharts::metricChart(QStringLiteral("Time"), QStringLiteral("s"),
                                {QPointF(1, 5.4), QPointF(2, 6.0)}, std::nullopt, 2));
  EXPECT_GT(darkPixelsUnderThePlot(metric.release()), 10);
}

TEST(ReviewCharts, AMetricNeverMeasuredInTheShownAttemptsHasNoChart) {
  QList<assessment::AttemptSummary> finished(2);
  finished[0].id = 1;
  finished[1].id = 2;
  // both attempts measured time; neither measured an entry angle (no pierce in the lesson)
  QList<QList<assessment::StoredMetric>> metrics(2);
  for (int i = 0; i < 2; ++i) {
    assessment::StoredMetric time;
    time.key = QStringLiteral("time");
    time.value = 100.0 + i;
    assessment::StoredMetric angle;
    angle.key = QStringLiteral("entry_angle");
    angle.value = std::nan("");
    metrics[i] << time << angle;
  }
  const assessment::Rubric rubric = rubricWith("time", 300.0, 60.0, assessment::BadSide::Above);
  TraineeHistoryView view;
  view.setHistory(finished, metrics, &rubric);
  const QList<QChart*> charts = view.metricCharts();
  ASSERT_EQ(charts.size(), 1);
  EXPECT_EQ(charts[0]->objectName(), QStringLiteral("time"));
  auto* values = qobject_cast<QLineSeries*>(seriesNamed(charts[0], kMetricSeriesName));
  ASSERT_NE(values, nullptr);
  EXPECT_EQ(values->count(), 2);

  // shown again with no attempts at all: no metric charts remain
  view.setHistory({}, {}, &rubric);
  EXPECT_TRUE(view.metricCharts().isEmpty());
}

// The history at the size an instructor's page gives it, with every key metric measured: the
// score chart keeps room for its plot (it had a third of the height, a 40-pixel plot and its
// attempt numbers elided to "…"), the metric charts scroll, and the attempts stay in view
TEST(ReviewCharts, TheScoreChartKeepsItsRoomWhenEveryMetricHasAChart) {
  QList<assessment::AttemptSummary> finished(2);
  QList<QList<assessment::StoredMetric>> metrics(2);
  for (int i = 0; i < 2; ++i) {
    finished[i].id = i + 1;
    finished[i].score = 40.0 + 20.0 * i;
    for (const char* key : {"entry_angle", "bite_walls", "time", "path_length"}) {
      assessment::StoredMetric m;
      m.key = QLatin1String(key);
      m.value = 1.0 + i;
      metrics[i] << m;
    }
  }
  const assessment::Rubric rubric = rubricWith("time", 300.0, 60.0, assessment::BadSide::Above);
  TraineeHistoryView view;
  view.setHistory(finished, metrics, &rubric);
  view.resize(1000, 600);
  view.show();
  QApplication::processEvents();
  ASSERT_EQ(view.metricCharts().size(), 4);
  EXPECT_GE(view.scoreChart()->plotArea().height(), 150.0);
  EXPECT_GE(view.attemptsTable()->height(), 100);
  for (QChart* chart : view.metricCharts())
    EXPECT_GE(chart->plotArea().height(), 80.0) << chart->objectName().toStdString();
}

TEST(ReviewCharts, AxesWriteNumbersInTheInterfacesLocale) {
  const QLocale previous;
  QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
  std::unique_ptr<QChart> metric(ReviewCharts::metricChart(QStringLiteral("Bite"), QStringLiteral("mm"),
                                                           {QPointF(1, 0.35), QPointF(2, 0.42)}, std::nullopt, 2));
  std::unique_ptr<QChart> score(ReviewCharts::scoreChart({62.5, 80.0}, 70.0));
  QLocale::setDefault(previous);
  for (const QChart* chart : {metric.get(), score.get()}) {
    EXPECT_TRUE(chart->localizeNumbers());
    EXPECT_EQ(chart->locale().decimalPoint(), QStringLiteral(","));
  }
}

}  // namespace
}  // namespace microsim::gui
