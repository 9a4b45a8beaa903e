// `microsim-cli score`'s report of the finished anastomosis: each end-product error is a row of
// the table, named in words, with its stitch and pierce numbered as the pierces are (from 1),
// its angle, measured value, limit and unit; the JSON gives the kind's stable key and 0-based
// indices (null for none); no error prints "none" and an empty list. The leak test is a line
// after the table and an object in the JSON, null without one.
#include "cli/score_report.h"

#include <QString>
#include <QStringList>
#include <QTextStream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

namespace {

using namespace microsim;
namespace as = microsim::assessment;

// a score with a wide bite at stitch 2's first pierce and a suture break nowhere in particular
as::AttemptScore scoreWithLapses() {
  as::AttemptScore s;
  as::EndProductError wide;
  wide.kind = as::EndProductErrorKind::WideBite;
  wide.stitch = 1;
  wide.passage = 2;
  wide.angleDeg = 135.0;
  wide.measured = 4.0;
  wide.limit = 3.0;
  as::EndProductError broken;
  broken.kind = as::EndProductErrorKind::SutureLineDisruption;
  broken.event = 7;
  s.endProduct = {wide, broken};
  return s;
}

QString scoreReportText(const as::AttemptScore& s) {
  QString text;
  QTextStream out(&text);
  cli::printScoreReport(out, s, as::Rubric{}, cli::ScoredFiles{});
  out.flush();
  return text;
}

// the first line of the report naming `name`, its runs of spaces made one; empty for none
QString scoreReportRow(const QString& text, const QString& name) {
  for (const QString& l : text.split(QLatin1Char('\n')))
    if (l.contains(name)) return l.simplified();
  return {};
}

TEST(ScoreReport, EachEndProductErrorIsARowWithItsPlaceAndNumbers) {
  const QString text = scoreReportText(scoreWithLapses());
  EXPECT_TRUE(text.contains(QStringLiteral("end product  lapse index 2"))) << text.toStdString();
  const auto row = [&](const QString& name) { return scoreReportRow(text, name); };
  EXPECT_EQ(row(QStringLiteral("wide bite")),
            QStringLiteral("1 wide bite 2 3 135.0 4.000 3.00 walls"));
  EXPECT_EQ(row(QStringLiteral("suture-line disruption")),
            QStringLiteral("2 suture-line disruption – – – – –"));
}

// the final scene's three (sim/scene/end_state_check.h): located by angle only, each in its unit
TEST(ScoreReport, TheFinalScenesLapsesAreRowsWithTheirAngleAndUnit) {
  as::AttemptScore s;
  const as::EndProductErrorKind kinds[3] = {as::EndProductErrorKind::OverTightStitch,
                                            as::EndProductErrorKind::ThreadInLumen,
                                            as::EndProductErrorKind::LargeEdgeOverlap};
  const double measured[3] = {0.4, 0.2, 0.09};
  const double limits[3] = {0.25, 0.05, 0.05};
  for (std::size_t k = 0; k < 3; ++k) {
    as::EndProductError e;
    e.kind = kinds[k];
    e.angleDeg = 100.0 * static_cast<double>(k + 1);
    e.measured = measured[k];
    e.limit = limits[k];
    s.endProduct.push_back(e);
  }
  const QString text = scoreReportText(s);
  const auto row = [&](const QString& name) { return scoreReportRow(text, name); };
  EXPECT_EQ(row(QStringLiteral("over-tight stitch")),
            QStringLiteral("1 over-tight stitch – – 100.0 0.400 0.25 1"));
  EXPECT_EQ(row(QStringLiteral("thread in the lumen")),
            QStringLiteral("2 thread in the lumen – – 200.0 0.200 0.05 mm"));
  EXPECT_EQ(row(QStringLiteral("large edge overlap")),
            QStringLiteral("3 large edge overlap – – 300.0 0.090 0.05 mm"));
  const nlohmann::json errors =
      cli::scoreReportJson(s, as::Rubric{}, cli::ScoredFiles{}).at("end_product");
  ASSERT_EQ(errors.size(), 3u);
  EXPECT_EQ(errors[0].at("kind"), "over_tight_stitch");
  EXPECT_EQ(errors[1].at("kind"), "thread_in_lumen");
  EXPECT_EQ(errors[2].at("kind"), "large_edge_overlap");
  EXPECT_EQ(errors[2].at("unit"), "mm");
  EXPECT_EQ(errors[2].at("angle_deg"), 300.0);
}

TEST(ScoreReport, TheJsonGivesEachErrorsKeyIndicesAndNumbers) {
  const nlohmann::json doc =
      cli::scoreReportJson(scoreWithLapses(), as::Rubric{}, cli::ScoredFiles{});
  const nlohmann::json& errors = doc.at("end_product");
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_EQ(errors[0].at("kind"), "wide_bite");
  EXPECT_EQ(errors[0].at("stitch"), 1);
  EXPECT_EQ(errors[0].at("pierce"), 2);
  EXPECT_EQ(errors[0].at("angle_deg"), 135.0);
  EXPECT_EQ(errors[0].at("measured"), 4.0);
  EXPECT_EQ(errors[0].at("limit"), 3.0);
  EXPECT_EQ(errors[0].at("unit"), "walls");
  EXPECT_EQ(errors[1].at("kind"), "suture_line_disruption");
  for (const char* field : {"stitch", "pierce", "angle_deg", "measured", "limit"})
    EXPECT_TRUE(errors[1].at(field).is_null()) << field;
}

TEST(ScoreReport, NoEndProductErrorIsSaidSo) {
  const QString text = scoreReportText(as::AttemptScore{});
  EXPECT_TRUE(text.contains(QStringLiteral("end product  lapse index 0\n  none\n")))
      << text.toStdString();
  EXPECT_TRUE(cli::scoreReportJson(as::AttemptScore{}, as::Rubric{}, cli::ScoredFiles{})
                  .at("end_product")
                  .empty());
}

as::AttemptScore scoreWithLeak(sim::LeakTestStatus status) {
  as::AttemptScore s;
  as::LeakFinding leak;
  leak.status = status;
  leak.pressureMmHg = 100.0;
  if (status == sim::LeakTestStatus::Solved) {
    leak.leaks = true;
    leak.largestGapMm = 0.1234;
    leak.angleDeg = 90.0;
    leak.limitMm = 0.05;
  }
  s.leak = leak;
  return s;
}

TEST(ScoreReport, TheLeakTestIsALineAfterTheTable) {
  const QString text = scoreReportText(scoreWithLeak(sim::LeakTestStatus::Solved));
  EXPECT_TRUE(text.endsWith(QStringLiteral(
      "\nleak test  100 mmHg: largest gap 0.123 mm at 90.0°, limit 0.050 mm  leaks\n")))
      << text.toStdString();
  EXPECT_TRUE(scoreReportText(scoreWithLeak(sim::LeakTestStatus::NoStitches))
                  .endsWith(QStringLiteral("leak test  not done: no stitch joins the two ends\n")));
  EXPECT_FALSE(scoreReportText(as::AttemptScore{}).contains(QStringLiteral("leak test")));
}

TEST(ScoreReport, TheJsonGivesTheLeakTestOrNull) {
  const nlohmann::json leak = cli::scoreReportJson(scoreWithLeak(sim::LeakTestStatus::Solved),
                                                   as::Rubric{}, cli::ScoredFiles{})
                                  .at("leak");
  EXPECT_EQ(leak.at("status"), "solved");
  EXPECT_EQ(leak.at("leaks"), true);
  EXPECT_EQ(leak.at("largest_gap_mm"), 0.1234);
  EXPECT_EQ(leak.at("angle_deg"), 90.0);
  EXPECT_EQ(leak.at("limit_mm"), 0.05);
  EXPECT_EQ(leak.at("pressure_mmhg"), 100.0);
  const nlohmann::json none =
      cli::scoreReportJson(scoreWithLeak(sim::LeakTestStatus::NoSeveredVessel), as::Rubric{},
                           cli::ScoredFiles{})
          .at("leak");
  EXPECT_EQ(none.at("status"), "no_severed_vessel");
  EXPECT_EQ(none.at("leaks"), false);
  EXPECT_TRUE(none.at("largest_gap_mm").is_null());
  EXPECT_TRUE(cli::scoreReportJson(as::AttemptScore{}, as::Rubric{}, cli::ScoredFiles{})
                  .at("leak")
                  .is_null());
}

}  // namespace
