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

TEST(ScoreReport, EachEndProductErrorIsARowWithItsPlaceAndNumbers) {
  const QString text = scoreReportText(scoreWithLapses());
  EXPECT_TRUE(text.contains(QStringLiteral("end product  lapse index 2"))) << text.toStdString();
  const QStringList lines = text.split(QLatin1Char('\n'));
  const auto row = [&](const QString& name) {
    for (const QString& l : lines)
      if (l.contains(name)) return l.simplified();
    return QString();
  };
  EXPECT_EQ(row(QStringLiteral("wide bite")),
            QStringLiteral("1 wide bite 2 3 135.0 4.000 3.00 walls"));
  EXPECT_EQ(row(QStringLiteral("suture-line disruption")),
            QStringLiteral("2 suture-line disruption – – – – –"));
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
