// The results page writes numbers as the interface language does: "26,9 s" and "0,3 mm" in
// German, never "26.9 s" beside "0,3 mm" (issue 20).
#include "gui/pages/results_page.h"

#include <QLocale>
#include <QSettings>
#include <QTableWidget>

#include <gtest/gtest.h>

namespace microsim::gui {
namespace {

// an attempt scored on time and bite, as the results page gets it
AttemptResult timeAndBiteResult() {
  AttemptResult result;
  result.scored = true;
  result.score.score = 62.4;
  assessment::MetricScore time;
  time.key = "time";
  time.unit = "s";
  time.value = 26.94;
  time.target = 60.0;
  time.points = 1.0;
  assessment::MetricScore bite;
  bite.key = "bite";
  bite.unit = "mm";
  bite.value = 0.3;
  bite.target = 0.45;
  bite.points = 0.62;
  result.score.metrics = {time, bite};
  return result;
}

// the metric table's value and points columns, row by row
QStringList shownValues(const ResultsPage& page) {
  const auto* table = page.findChild<QTableWidget*>(QStringLiteral("metricTable"));
  QStringList values;
  if (!table) return values;
  for (int row = 0; row < table->rowCount(); ++row)
    values << table->item(row, 1)->text() + QStringLiteral(" | ") + table->item(row, 2)->text();
  return values;
}

QStringList valuesShownIn(const QLocale& locale) {
  const QLocale previous;
  QLocale::setDefault(locale);
  ResultsPage page;
  page.show(timeAndBiteResult(), QStringLiteral("Needle entry"));
  QStringList values = shownValues(page);
  QLocale::setDefault(previous);
  return values;
}

TEST(ResultsPage, WritesNumbersInTheLocalesFormat) {
  QSettings().clear();
  EXPECT_EQ(valuesShownIn(QLocale(QLocale::German, QLocale::Germany)),
            (QStringList{QStringLiteral("26,9 s (target 60 s) | 100 %"), QStringLiteral("0,3 mm (target 0,45 mm) | 62 %")}));
  EXPECT_EQ(valuesShownIn(QLocale(QLocale::English, QLocale::UnitedStates)),
            (QStringList{QStringLiteral("26.9 s (target 60 s) | 100 %"), QStringLiteral("0.3 mm (target 0.45 mm) | 62 %")}));
}

TEST(ResultsPage, ShowsLengthsInTheChosenUnits) {
  QSettings().setValue(QStringLiteral("view/units"), QStringLiteral("um"));
  const QStringList values = valuesShownIn(QLocale(QLocale::German, QLocale::Germany));
  QSettings().clear();
  ASSERT_EQ(values.size(), 2);
  EXPECT_EQ(values[1], QStringLiteral("300 µm (target 450 µm) | 62 %"));
}

}  // namespace
}  // namespace microsim::gui
