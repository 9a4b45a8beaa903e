// The results page writes numbers as the interface language does: "26,9 s" and "0,3 mm" in
// German, never "26.9 s" beside "0,3 mm" (issue 20).
#include "gui/pages/results_page.h"

#include "gui/pages/end_product_panel.h"

#include <QLabel>
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

// one stitch whose second passage caught the back wall, at 183° round the vessel
AttemptResult backWallStitchResult() {
  AttemptResult result = timeAndBiteResult();
  assessment::PierceMetrics front;
  front.end = 0;
  front.circumferenceDeg = 175.0;
  front.biteWalls = 2.4;
  front.fullThickness = true;
  assessment::PierceMetrics back = front;
  back.end = 1;
  back.circumferenceDeg = 183.0;
  back.backWall = true;
  result.score.pierces = {front, back};
  assessment::StitchMetrics stitch;
  stitch.first = 0;
  stitch.second = 1;
  stitch.positionDeg = 179.0;
  result.score.stitches = {stitch};
  assessment::EndProductError e;
  e.kind = assessment::EndProductErrorKind::BackWallStitch;
  e.stitch = 0;
  e.passage = 1;
  e.angleDeg = 183.0;
  result.score.endProduct = {e};
  return result;
}

TEST(ResultsPage, ListsABackWallStitchAndShowsTheOpenedVessel) {
  QSettings().clear();
  QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates));
  ResultsPage page;
  page.show(backWallStitchResult(), QStringLiteral("Single stitch"));
  const auto* panel = page.findChild<EndProductPanel*>(QStringLiteral("endProductPanel"));
  ASSERT_NE(panel, nullptr);
  const QTableWidget* table = panel->errorTable();
  ASSERT_EQ(table->rowCount(), 1);
  EXPECT_FALSE(table->isHidden());
  EXPECT_EQ(table->item(0, 0)->text(), QStringLiteral("1"));
  EXPECT_EQ(table->item(0, 1)->text(), QStringLiteral("back-wall stitch"));
  EXPECT_EQ(table->item(0, 2)->text(), QStringLiteral("stitch 1, pierce 2, at 183°"));
  EXPECT_EQ(table->item(0, 3)->text(), QStringLiteral("–"));
  EXPECT_TRUE(panel->summaryLabel()->text().endsWith(QStringLiteral("Lapse Index): 1")))
      << panel->summaryLabel()->text().toStdString();
  // the opened vessel is drawn, with its one marker
  const auto* picture = page.findChild<QLabel*>(QStringLiteral("openedVesselImage"));
  ASSERT_NE(picture, nullptr);
  EXPECT_FALSE(picture->pixmap().isNull());
  EXPECT_EQ(panel->image().size(), EndProductPanel::imageSize());
  const OpenedVesselLayout layout = OpenedVesselImage::layOut(
      {backWallStitchResult().score.pierces, backWallStitchResult().score.stitches,
       backWallStitchResult().score.endProduct},
      EndProductPanel::imageSize());
  ASSERT_EQ(layout.marks.size(), 1u);
  EXPECT_GT(layout.marks[0].at.y(), layout.sutureLineY);  // the second passage, through end 2
}

TEST(ResultsPage, SaysWhenTheEndProductIsClean) {
  QSettings().clear();
  ResultsPage page;
  page.show(timeAndBiteResult(), QStringLiteral("Needle entry"));
  const auto* panel = page.findChild<EndProductPanel*>(QStringLiteral("endProductPanel"));
  ASSERT_NE(panel, nullptr);
  EXPECT_EQ(panel->summaryLabel()->text(), QStringLiteral("No end-product errors."));
  EXPECT_EQ(panel->errorTable()->rowCount(), 0);
  EXPECT_TRUE(panel->errorTable()->isHidden());
}

TEST(EndProductPanel, NamesWhatWasMeasuredAgainstItsLimit) {
  const QLocale previous;
  QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
  assessment::EndProductError wide;
  wide.kind = assessment::EndProductErrorKind::WideBite;
  wide.passage = 0;
  wide.angleDeg = 12.4;
  wide.measured = 3.44;
  wide.limit = 3.0;
  EXPECT_EQ(EndProductPanel::measured(wide), QStringLiteral("3,4 wall thicknesses (limit 3)"));
  EXPECT_EQ(EndProductPanel::where(wide), QStringLiteral("pierce 1, at 12°"));
  assessment::EndProductError tear;
  tear.kind = assessment::EndProductErrorKind::WallTear;
  tear.measured = 2;
  EXPECT_EQ(EndProductPanel::measured(tear), QStringLiteral("links torn: 2"));
  EXPECT_EQ(EndProductPanel::where(tear), QStringLiteral("not located"));
  EXPECT_TRUE(EndProductPanel::summary({}, false).contains(QStringLiteral("not judged")));
  // the final scene's three and the leak, each against its limit in its unit
  const auto endState = [](assessment::EndProductErrorKind kind, double measured, double limit) {
    assessment::EndProductError e;
    e.kind = kind;
    e.angleDeg = 90.0;
    e.measured = measured;
    e.limit = limit;
    return e;
  };
  using K = assessment::EndProductErrorKind;
  EXPECT_EQ(EndProductPanel::measured(endState(K::OverTightStitch, 0.4, 0.25)),
            QStringLiteral("bites squeezed by 40 % (limit 25 %)"));
  EXPECT_EQ(EndProductPanel::measured(endState(K::ThreadInLumen, 0.2, 0.05)),
            QStringLiteral("0,2 mm into the lumen (limit 0,05 mm)"));
  EXPECT_EQ(EndProductPanel::measured(endState(K::LargeEdgeOverlap, 0.09, 0.05)),
            QStringLiteral("edges past each other, 0,09 mm out of line (limit 0,05 mm)"));
  EXPECT_EQ(EndProductPanel::measured(endState(K::SutureLineDisruption, 0.12, 0.05)),
            QStringLiteral("0,12 mm (limit 0,05 mm)"));
  QLocale::setDefault(previous);
}

}  // namespace
}  // namespace microsim::gui
