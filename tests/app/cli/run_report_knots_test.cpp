// `microsim-cli run`'s report of knot events: a scene whose thread is tied in a surgeon's knot
// (support/knot_scene.h) prints one line per throw formed, with its handedness, wraps and the
// knot's name, and its JSON gives each event's kind and knot (type, throws, tension, the throw's
// handedness and wraps); the shipped stitch, which ties no knot, has no knot event in either.
#include "cli/run_report.h"

#include "support/knot_scene.h"
#include "support/shipped_files.h"

#include <QString>
#include <QStringList>
#include <QTextStream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

namespace {

using namespace microsim;

// the report as printed and as JSON text (parsed where it is read: a json member would make
// the struct's implicit members ones that may throw)
struct KnotRun {
  QString text;
  std::string json;
};

KnotRun reportOfSurgeonsKnot(int frames) {
  const std::optional<sim::SceneDef> def =
      microsim::testing::surgeonsKnotSceneDef(microsim::testing::kSourceRoot.toStdString());
  EXPECT_TRUE(def);
  sim::Scene scene(*def);
  const sim::Points start = scene.sutureState()->x;
  cli::StepTimeLog times;
  for (int k = 0; k < frames; ++k)
    times.add(scene.step(microsim::testing::knotPullFrame(start, k)).times);
  KnotRun run;
  QTextStream out(&run.text);
  cli::printRunReport(out, scene, QStringLiteral("knot.json"), times);
  out.flush();
  run.json = cli::runReportJson(scene, QStringLiteral("knot.json"), times);
  return run;
}

TEST(RunReportKnots, EachThrowOfASurgeonsKnotIsALineAndAJsonEvent) {
  const KnotRun run = reportOfSurgeonsKnot(10);
  const QStringList lines = run.text.split(QLatin1Char('\n'));
  QStringList knotLines;
  for (const QString& line : lines)
    if (line.contains(QStringLiteral("formed"))) knotLines << line.trimmed();
  ASSERT_EQ(knotLines.size(), 2);
  EXPECT_EQ(knotLines[0].toStdString(),
            "0.02 s  throw 1 formed: left-handed, 2 wrap(s); the knot reads a surgeon's knot");
  EXPECT_EQ(knotLines[1].toStdString(),
            "0.02 s  throw 2 formed: right-handed, 1 wrap(s); the knot reads a surgeon's knot");

  std::vector<nlohmann::json> knots;
  const nlohmann::json report = nlohmann::json::parse(run.json);
  for (const nlohmann::json& e : report.at("events"))
    if (e.at("kind") == "throw-formed") knots.push_back(e);
  ASSERT_EQ(knots.size(), 2U);
  EXPECT_EQ(knots[0].at("knot").at("type"), "surgeons");
  EXPECT_EQ(knots[0].at("knot").at("throws"), 2);
  EXPECT_EQ(knots[0].at("knot").at("throw"), 0);
  EXPECT_EQ(knots[0].at("knot").at("handedness"), "left");
  EXPECT_EQ(knots[0].at("knot").at("wraps"), 2);
  EXPECT_EQ(knots[1].at("knot").at("throw"), 1);
  EXPECT_EQ(knots[1].at("knot").at("handedness"), "right");
  EXPECT_EQ(knots[1].at("knot").at("wraps"), 1);
  EXPECT_TRUE(knots[1].at("knot").contains("tension_uN"));
}

}  // namespace
