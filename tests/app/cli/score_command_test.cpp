// `microsim-cli score` as a user runs it: the shipped stitch scores the pinned value with
// the single-stitch rubric (table and JSON) and shows no end-product error, the scene comes
// from the recording when it names one (and is looked for when it moved), --db stores the
// attempt, and bad rubrics, recordings and arguments fail with a message naming the problem.
#include "support/cli_runner.h"
#include "support/golden_stitch.h"

#include "microsim/assessment/storage/attempt_store.h"
#include "microsim/assessment/storage/history_database.h"
#include "microsim/assessment/storage/people_store.h"
#include "microsim/sim/scene/recorded_scene.h"
#include "microsim/sim/scene/recording.h"
#include "support/scene_copy.h"
#include "support/shipped_files.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace {

using microsim::testing::CliRun;
using microsim::testing::runCli;

using microsim::testing::kShippedRubric;
using microsim::testing::kShippedScene;
using microsim::testing::kShippedStitch;
using microsim::testing::kSourceRoot;
constexpr double kStitchScore = microsim::testing::kGoldenStitchScoreSingleStitch;

QJsonObject readScoreJson(const QString& path) {
  QFile f(path);
  if (!f.open(QIODevice::ReadOnly)) return {};
  return QJsonDocument::fromJson(f.readAll()).object();
}

CliRun score(const QStringList& extra) {
  return runCli(QStringList{QStringLiteral("score"), QStringLiteral("--rubric"), kShippedRubric} + extra);
}

TEST(ScoreCommand, TheShippedStitchScoresThePinnedValueInTheTableAndTheJson) {
  QTemporaryDir dir;
  const QString out = dir.filePath(QStringLiteral("score.json"));
  const CliRun r = score({QStringLiteral("--recording"), kShippedStitch, QStringLiteral("--scene"), kShippedScene,
                          QStringLiteral("--json"), out});
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();
  EXPECT_TRUE(r.out.contains(QStringLiteral("score  ") + QString::number(kStitchScore, 'f', 1)))
      << r.out.toStdString();
  // the stitch is neither tied nor cut, which lesson 3 asks for
  for (const char* key : {"entry_angle.too_oblique", "knot.not_tied", "knot.not_secure", "cut.not_done"})
    EXPECT_TRUE(r.out.contains(QLatin1String(key))) << key << "\n" << r.out.toStdString();
  const QJsonObject doc = readScoreJson(out);
  EXPECT_NEAR(doc.value(QStringLiteral("score")).toDouble(), kStitchScore, 1e-9);
  EXPECT_FALSE(doc.value(QStringLiteral("passed")).toBool());
  EXPECT_FALSE(doc.value(QStringLiteral("truncated")).toBool());
  EXPECT_EQ(doc.value(QStringLiteral("rubric")).toObject().value(QStringLiteral("id")).toString(),
            QStringLiteral("03_single_stitch"));
  EXPECT_EQ(doc.value(QStringLiteral("rubric")).toObject().value(QStringLiteral("version")).toInt(),
            3);
  const QJsonArray metrics = doc.value(QStringLiteral("metrics")).toArray();
  ASSERT_EQ(metrics.size(), 15);
  for (const QJsonValue& m : metrics)
    for (const char* field : {"key", "value", "unit", "target", "points", "feedback"})
      EXPECT_TRUE(m.toObject().contains(QLatin1String(field))) << field;
  EXPECT_EQ(doc.value(QStringLiteral("pierces")).toArray().size(), 2);
  // one clean stitch: no lapse of the finished anastomosis (end_product_test.cpp says why)
  EXPECT_TRUE(r.out.contains(QStringLiteral("end product  lapse index 0\n  none\n"))) << r.out.toStdString();
  ASSERT_TRUE(doc.value(QStringLiteral("end_product")).isArray());
  EXPECT_TRUE(doc.value(QStringLiteral("end_product")).toArray().isEmpty());
  // the leak test on the final scene: one stitch holds the ends at one point, the line leaks
  // opposite it (tests/sim/scene/leak_test_test.cpp)
  const QJsonObject leak = doc.value(QStringLiteral("leak")).toObject();
  EXPECT_EQ(leak.value(QStringLiteral("status")).toString(), QStringLiteral("solved"));
  EXPECT_TRUE(leak.value(QStringLiteral("leaks")).toBool());
  const double gap = leak.value(QStringLiteral("largest_gap_mm")).toDouble();
  const double angle = leak.value(QStringLiteral("angle_deg")).toDouble();
  EXPECT_GT(gap, 0.5);
  EXPECT_NEAR(angle, 180.0, 45.0);
  EXPECT_TRUE(r.out.contains(
      QStringLiteral("leak test  100 mmHg: largest gap %1 mm at %2°, limit 0.050 mm  leaks")
          .arg(gap, 0, 'f', 3)
          .arg(angle, 0, 'f', 1)))
      << r.out.toStdString();

  // the same every run
  const QString again = dir.filePath(QStringLiteral("again.json"));
  ASSERT_EQ(score({QStringLiteral("--recording"), kShippedStitch, QStringLiteral("--scene"), kShippedScene,
                   QStringLiteral("--json"), again})
                .exitCode,
            0);
  EXPECT_EQ(readScoreJson(again).value(QStringLiteral("score")).toDouble(), doc.value(QStringLiteral("score")).toDouble());
}

// The GUI's lesson flow (tests/app/gui/lesson_flow_test.cpp) is held to the same value, so
// the app and the CLI score lesson 2 alike.
TEST(ScoreCommand, TheShippedStitchScoresLesson2sPinnedValue) {
  QTemporaryDir dir;
  const QString out = dir.filePath(QStringLiteral("score.json"));
  const CliRun r = runCli({QStringLiteral("score"), QStringLiteral("--rubric"),
                           kSourceRoot + QStringLiteral("/resources/rubrics/02_needle_entry.json"),
                           QStringLiteral("--recording"), kShippedStitch, QStringLiteral("--scene"), kShippedScene,
                           QStringLiteral("--json"), out});
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();
  EXPECT_TRUE(
      r.out.contains(QStringLiteral("score  ") +
                     QString::number(microsim::testing::kGoldenStitchScoreNeedleEntry, 'f', 1)))
      << r.out.toStdString();
  EXPECT_NEAR(readScoreJson(out).value(QStringLiteral("score")).toDouble(),
              microsim::testing::kGoldenStitchScoreNeedleEntry, 1e-9);
}

// The shipped back-wall catch names its scene (found among the shipped ones): the catch is a
// never-event that caps the score at 0, and the end-product check lists it, with the thread it
// leaves across the lumen, at the place on the circumference where the back wall was taken.
TEST(ScoreCommand, TheShippedBackWallCatchIsANeverEventTheEndProductCheckFinds) {
  QTemporaryDir dir;
  const QString out = dir.filePath(QStringLiteral("score.json"));
  const CliRun r = score({QStringLiteral("--recording"), microsim::testing::kShippedBackWallCatch,
                          QStringLiteral("--json"), out});
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();
  EXPECT_TRUE(r.out.contains(
      QStringLiteral("score  0.0  not passed\n  never-event  never.back_wall_catch\n")))
      << r.out.toStdString();
  const QJsonObject doc = readScoreJson(out);
  EXPECT_EQ(doc.value(QStringLiteral("score")).toDouble(), 0.0);
  const QJsonArray pierces = doc.value(QStringLiteral("pierces")).toArray();
  ASSERT_EQ(pierces.size(), 2);
  EXPECT_FALSE(pierces[0].toObject().value(QStringLiteral("back_wall")).toBool());
  EXPECT_TRUE(pierces[1].toObject().value(QStringLiteral("back_wall")).toBool());
  QStringList kinds;
  for (const QJsonValue& e : doc.value(QStringLiteral("end_product")).toArray())
    kinds << e.toObject().value(QStringLiteral("kind")).toString();
  EXPECT_TRUE(kinds.contains(QStringLiteral("back_wall_stitch")))
      << kinds.join(QLatin1Char(' ')).toStdString();
  EXPECT_TRUE(kinds.contains(QStringLiteral("thread_in_lumen")))
      << kinds.join(QLatin1Char(' ')).toStdString();
  EXPECT_TRUE(r.out.contains(QStringLiteral("back-wall stitch"))) << r.out.toStdString();
}

// writes `rec` to `path`
bool writeRecording(const QString& path, const microsim::sim::Recording& rec) {
  const std::vector<std::uint8_t> bytes = microsim::sim::encodeRecording(rec);
  QFile f(path);
  return f.open(QIODevice::WriteOnly) &&
         f.write(reinterpret_cast<const char*>(bytes.data()), static_cast<qint64>(bytes.size())) ==
             static_cast<qint64>(bytes.size());
}

TEST(ScoreCommand, TheSceneComesFromTheRecordingOrMustBeGiven) {
  // the shipped stitch (format version 1) names no scene
  CliRun r = score({QStringLiteral("--recording"), kShippedStitch});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(r.err.contains(QStringLiteral("names no scene: give --scene FILE"))) << r.err.toStdString();

  // a copy whose header names it scores the same
  QTemporaryDir dir;
  microsim::sim::Recording rec;
  ASSERT_TRUE(microsim::sim::readRecording(kShippedStitch.toStdString(), rec).ok());
  rec.scene = microsim::sim::recordScene(kShippedScene.toStdString());
  const QString named = dir.filePath(QStringLiteral("named.msrec"));
  ASSERT_TRUE(writeRecording(named, rec));
  const QString out = dir.filePath(QStringLiteral("named.json"));
  r = score({QStringLiteral("--recording"), named, QStringLiteral("--json"), out});
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();
  EXPECT_NEAR(readScoreJson(out).value(QStringLiteral("score")).toDouble(), kStitchScore, 1e-9);
  EXPECT_EQ(readScoreJson(out).value(QStringLiteral("scene")).toString(), kShippedScene);

  // the app's recordings before version 2 named it in their metadata, and still score
  microsim::sim::Recording version1Style = rec;
  version1Style.scene = {};
  version1Style.metadata = "{\"scene\": \"" + kShippedScene.toStdString() + "\"}";
  const QString fromMetadata = dir.filePath(QStringLiteral("metadata.msrec"));
  ASSERT_TRUE(writeRecording(fromMetadata, version1Style));
  const QString metadataOut = dir.filePath(QStringLiteral("metadata.json"));
  r = score({QStringLiteral("--recording"), fromMetadata, QStringLiteral("--json"), metadataOut});
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();
  EXPECT_NEAR(readScoreJson(metadataOut).value(QStringLiteral("score")).toDouble(), kStitchScore, 1e-9);
  const std::vector<std::uint8_t> bytes = microsim::sim::encodeRecording(rec);

  // a truncated copy scores what it holds and says so
  const QString cut = dir.filePath(QStringLiteral("cut.msrec"));
  QFile c(cut);
  ASSERT_TRUE(c.open(QIODevice::WriteOnly));
  c.write(reinterpret_cast<const char*>(bytes.data()), static_cast<qint64>(bytes.size() / 2));
  c.close();
  const QString cutOut = dir.filePath(QStringLiteral("cut.json"));
  r = score({QStringLiteral("--recording"), cut, QStringLiteral("--json"), cutOut});
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();
  EXPECT_TRUE(r.err.contains(QStringLiteral("unfinished"))) << r.err.toStdString();
  EXPECT_TRUE(readScoreJson(cutOut).value(QStringLiteral("truncated")).toBool());
}

// `run --record` names the scene in the recording; `score` finds it where it was, beside the
// recording when it moved there, and says which scene it looked for, and where, when it is gone
TEST(ScoreCommand, AFreshRecordingIsScoredOnItsOwnSceneOrNamesTheSceneItLacks) {
  QTemporaryDir dir;
  const QString scene = microsim::testing::copyShippedScene(dir.path(), QStringLiteral("moving.json"));
  ASSERT_FALSE(scene.isEmpty());
  const QString recording = dir.filePath(QStringLiteral("attempts/fresh.msrec"));
  ASSERT_TRUE(QDir(dir.path()).mkpath(QStringLiteral("attempts")));
  CliRun r = runCli({QStringLiteral("run"), QStringLiteral("--scene"), scene, QStringLiteral("--script"),
                     QStringLiteral("stitch"), QStringLiteral("--frames"), QStringLiteral("300"),
                     QStringLiteral("--record"), recording});
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();

  // on the scene it names, as with --scene
  const QString named = dir.filePath(QStringLiteral("named.json"));
  const QString given = dir.filePath(QStringLiteral("given.json"));
  r = score({QStringLiteral("--recording"), recording, QStringLiteral("--json"), named});
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();
  ASSERT_EQ(score({QStringLiteral("--recording"), recording, QStringLiteral("--scene"), scene, QStringLiteral("--json"),
                   given})
                .exitCode,
            0);
  EXPECT_EQ(readScoreJson(named).value(QStringLiteral("scene")).toString(), scene);
  EXPECT_EQ(readScoreJson(named).value(QStringLiteral("score")).toDouble(),
            readScoreJson(given).value(QStringLiteral("score")).toDouble());
  EXPECT_EQ(readScoreJson(named).value(QStringLiteral("frames")).toInt(), 300);

  // moved beside the recording (its mesh still at ../meshes): found there
  const QString beside = dir.filePath(QStringLiteral("attempts/moving.json"));
  ASSERT_TRUE(QFile::rename(scene, beside));
  const QString moved = dir.filePath(QStringLiteral("moved.json"));
  r = score({QStringLiteral("--recording"), recording, QStringLiteral("--json"), moved});
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();
  EXPECT_EQ(readScoreJson(moved).value(QStringLiteral("scene")).toString(), beside);
  EXPECT_EQ(readScoreJson(moved).value(QStringLiteral("score")).toDouble(),
            readScoreJson(given).value(QStringLiteral("score")).toDouble());
  EXPECT_FALSE(r.err.contains(QStringLiteral("warning"))) << r.err.toStdString();

  // edited since: scored, with a warning
  QFile edit(beside);
  ASSERT_TRUE(edit.open(QIODevice::Append));
  edit.write("\n");
  edit.close();
  r = score({QStringLiteral("--recording"), recording});
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();
  EXPECT_TRUE(r.err.contains(QStringLiteral("microsim-cli score: warning: %1 has changed since the recording was made "
                                            "on it (%2)")
                                 .arg(beside, scene)))
      << r.err.toStdString();

  // gone: the scene it was made on, where it was looked for, and what to do
  ASSERT_TRUE(QFile::remove(beside));
  r = score({QStringLiteral("--recording"), recording});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_TRUE(r.out.isEmpty()) << r.out.toStdString();
  EXPECT_TRUE(r.err.contains(QStringLiteral("microsim-cli score: the recording was made on the scene %1, which is "
                                            "not there")
                                 .arg(scene)))
      << r.err.toStdString();
  EXPECT_TRUE(r.err.contains(beside)) << r.err.toStdString();
  EXPECT_TRUE(r.err.contains(QStringLiteral("give --scene FILE"))) << r.err.toStdString();

  // --scene still says which
  r = score({QStringLiteral("--recording"), recording, QStringLiteral("--scene"), kShippedScene});
  EXPECT_EQ(r.exitCode, 0) << r.err.toStdString();
}

TEST(ScoreCommand, WithADatabaseTheAttemptIsStoredForTheTrainee) {
  QTemporaryDir dir;
  const QString db = dir.filePath(QStringLiteral("history.sqlite"));
  const QString out = dir.filePath(QStringLiteral("score.json"));
  const CliRun r = score({QStringLiteral("--recording"), kShippedStitch, QStringLiteral("--scene"), kShippedScene,
                          QStringLiteral("--db"), db, QStringLiteral("--trainee"), QStringLiteral("Ada"),
                          QStringLiteral("--json"), out});
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();
  const qint64 id = static_cast<qint64>(readScoreJson(out).value(QStringLiteral("attempt_id")).toDouble());
  EXPECT_GT(id, 0);

  microsim::assessment::HistoryDatabase history;
  ASSERT_TRUE(history.open(db).ok());
  qint64 ada = 0;
  for (const auto& t : microsim::assessment::PeopleStore(history).trainees())
    if (t.name == QStringLiteral("Ada")) ada = t.id;
  ASSERT_GT(ada, 0);
  const auto attempts = microsim::assessment::AttemptStore(history).list({ada, microsim::assessment::Role::Trainee});
  ASSERT_EQ(attempts.size(), 1);
  EXPECT_EQ(attempts[0].id, id);
  EXPECT_EQ(attempts[0].lesson, QStringLiteral("03_single_stitch"));
  EXPECT_EQ(attempts[0].rubricId, QStringLiteral("03_single_stitch"));
  EXPECT_EQ(attempts[0].rubricVersion, 3);
  ASSERT_TRUE(attempts[0].score.has_value());
  EXPECT_NEAR(*attempts[0].score, kStitchScore, 1e-9);
}

TEST(ScoreCommand, BadInputsFailWithAMessage) {
  QTemporaryDir dir;
  const QString broken = dir.filePath(QStringLiteral("broken.json"));
  QFile f(broken);
  ASSERT_TRUE(f.open(QIODevice::WriteOnly));
  f.write("{\"id\": \"x\", \"version\": 1, \"pass_mark\": 50,\n \"metrics\": [{\"key\": \"nope\", \"weight\": 1, "
          "\"target\": 0, \"tolerance\": 1, \"limit\": 2, \"bad\": \"both\"}]}");
  f.close();
  CliRun r = runCli({QStringLiteral("score"), QStringLiteral("--recording"), kShippedStitch, QStringLiteral("--scene"),
                     kShippedScene, QStringLiteral("--rubric"), broken});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_TRUE(r.err.contains(broken + QStringLiteral(":2:"))) << r.err.toStdString();
  EXPECT_TRUE(r.err.contains(QStringLiteral("unknown metric (field metrics[0].key)"))) << r.err.toStdString();

  r = score({QStringLiteral("--recording"), kShippedScene, QStringLiteral("--scene"), kShippedScene});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_TRUE(r.err.contains(QStringLiteral("not a microsim recording"))) << r.err.toStdString();

  r = score({QStringLiteral("--recording"), kShippedStitch, QStringLiteral("--scene"), dir.filePath(QStringLiteral("no.json"))});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_TRUE(r.err.contains(QStringLiteral("no.json"))) << r.err.toStdString();

  EXPECT_EQ(runCli({QStringLiteral("score"), QStringLiteral("--recording"), kShippedStitch}).exitCode, 2);
  EXPECT_EQ(score({QStringLiteral("--recording"), kShippedStitch, QStringLiteral("--db"), dir.filePath(QStringLiteral("h.sqlite"))})
                .exitCode,
            2);
  EXPECT_EQ(score({QStringLiteral("--recording"), kShippedStitch, QStringLiteral("--mode"), QStringLiteral("exam")}).exitCode, 2);
}

}  // namespace
