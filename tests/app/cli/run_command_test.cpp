// `microsim-cli run` as a user runs it: the shipped stitch replays to the golden hash with its
// four pierces and no knot; a recording made with --record replays to the same hash, on the scene it
// names when --scene is not given; damaged recordings, missing and broken scenes fail with a
// message naming the file, and no crash.
#include "support/golden_stitch.h"
#include "support/cli_runner.h"
#include "support/scene_copy.h"
#include "support/shipped_files.h"

#include "microsim/sim/scene/recorded_scene.h"
#include "microsim/sim/scene/recording.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace {

using microsim::testing::CliRun;
using microsim::testing::runCli;

using microsim::testing::kShippedScene;
using microsim::testing::kShippedStitch;
// tests/sim/scene/stitch_test.cpp holds the same value
const QString kGolden = QString::fromLatin1(microsim::testing::kGoldenStitchHashText);

QJsonObject readRunJson(const QString& path) {
  QFile f(path);
  if (!f.open(QIODevice::ReadOnly)) return {};
  return QJsonDocument::fromJson(f.readAll()).object();
}

TEST(RunCommand, TheShippedStitchReplaysToTheGoldenHashWithFourPierces) {
  QTemporaryDir dir;
  const QString out = dir.filePath(QStringLiteral("run.json"));
  const CliRun r = runCli({QStringLiteral("run"), QStringLiteral("--scene"), kShippedScene, QStringLiteral("--input"),
                           kShippedStitch, QStringLiteral("--json"), out});
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();
  EXPECT_TRUE(r.out.contains(kGolden)) << r.out.toStdString();
  const QJsonObject doc = readRunJson(out);
  EXPECT_EQ(doc.value(QStringLiteral("hash")).toString(), kGolden);
  int pierces = 0;
  for (const QJsonValue& v : doc.value(QStringLiteral("events")).toArray()) {
    const QString kind = v.toObject().value(QStringLiteral("kind")).toString();
    // two passes through two walls tie no knot
    EXPECT_FALSE(kind.startsWith(QStringLiteral("knot-")) || kind == QStringLiteral("throw-formed")) << kind.toStdString();
    if (kind.startsWith(QStringLiteral("pierce-"))) {
      ++pierces;
      EXPECT_TRUE(v.toObject().value(QStringLiteral("pierce")).toObject().contains(QStringLiteral("angle_deg")));
    }
  }
  EXPECT_EQ(pierces, 4);
  for (const char* stage : {"collision", "tissue", "suture", "interactions", "total"})
    EXPECT_TRUE(doc.value(QStringLiteral("timings_ms")).toObject().contains(QLatin1String(stage))) << stage;
}

// glibc picks its exp, expm1, sin, … at load time by what the CPU offers, and the variants
// that use FMA may round the last bit otherwise. A replay scored on another machine must give
// the same states: with those variants turned off, the stitch replays to the same hash.
TEST(RunCommand, TheShippedStitchReplaysToTheGoldenHashWhicheverMathLibraryTheCpuGets) {
  QProcessEnvironment plainMath;
  plainMath.insert(QStringLiteral("GLIBC_TUNABLES"),
                   QStringLiteral("glibc.cpu.hwcaps=-AVX2,-FMA,-AVX"));
  const CliRun r = runCli({QStringLiteral("run"), QStringLiteral("--scene"), kShippedScene,
                           QStringLiteral("--input"), kShippedStitch},
                          120000, {}, plainMath);
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();
  EXPECT_TRUE(r.out.contains(kGolden)) << r.out.toStdString();
}

// The shipped back-wall catch names its scene: `run --input` alone finds it and replays the
// script's frames (generated again with --script) to the pinned hash.
TEST(RunCommand, TheBackWallCatchScriptIsTheShippedRecording) {
  QTemporaryDir dir;
  const QString shipped = dir.filePath(QStringLiteral("shipped.json"));
  const QString scripted = dir.filePath(QStringLiteral("scripted.json"));
  CliRun r = runCli({QStringLiteral("run"), QStringLiteral("--input"),
                     microsim::testing::kShippedBackWallCatch, QStringLiteral("--json"), shipped});
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();
  r = runCli({QStringLiteral("run"), QStringLiteral("--scene"), kShippedScene,
              QStringLiteral("--script"), QStringLiteral("back-wall-catch"),
              QStringLiteral("--json"), scripted});
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();
  const QString hash = QStringLiteral("%1").arg(microsim::testing::kGoldenBackWallCatchHash, 16, 16,
                                                QLatin1Char('0'));
  EXPECT_EQ(readRunJson(shipped).value(QStringLiteral("hash")).toString(), hash);
  EXPECT_EQ(readRunJson(scripted).value(QStringLiteral("hash")).toString(), hash);
  int pierces = 0;
  for (const QJsonValue& v : readRunJson(shipped).value(QStringLiteral("events")).toArray())
    pierces +=
        v.toObject().value(QStringLiteral("kind")).toString().startsWith(QStringLiteral("pierce-"))
            ? 1
            : 0;
  EXPECT_EQ(pierces, 4);

  // a scene without a severed vessel has no catch to script: named, and nothing is run
  r = runCli(
      {QStringLiteral("run"), QStringLiteral("--scene"),
       microsim::testing::kSourceRoot + QStringLiteral("/resources/scenes/single_vessel.json"),
       QStringLiteral("--script"), QStringLiteral("back-wall-catch")});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_TRUE(r.err.contains(QStringLiteral(
      "the script 'back-wall-catch' needs a severed vessel, a curved needle and two forceps")))
      << r.err.toStdString();
  EXPECT_FALSE(r.out.contains(QStringLiteral("state hash"))) << r.out.toStdString();

  r = runCli({QStringLiteral("run"), QStringLiteral("--scene"), kShippedScene,
              QStringLiteral("--script"), QStringLiteral("knot")});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(
      r.err.contains(QStringLiteral("unknown script 'knot' (known: stitch, back-wall-catch)")))
      << r.err.toStdString();
}

TEST(RunCommand, ARecordedRunReplaysToTheSameHashOnTheSceneItNamesUnlessToldOtherwise) {
  QTemporaryDir dir;
  const QString scene = microsim::testing::copyShippedScene(dir.path(), QStringLiteral("mine.json"));
  ASSERT_FALSE(scene.isEmpty());
  const QString rec = dir.filePath(QStringLiteral("a.msrec"));
  const QString first = dir.filePath(QStringLiteral("first.json"));
  const QString second = dir.filePath(QStringLiteral("second.json"));
  CliRun r = runCli({QStringLiteral("run"), QStringLiteral("--scene"), scene, QStringLiteral("--script"),
                     QStringLiteral("stitch"), QStringLiteral("--frames"), QStringLiteral("120"),
                     QStringLiteral("--record"), rec, QStringLiteral("--json"), first});
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();

  // the recording names the scene, absolute, with its digest
  microsim::sim::Recording recorded;
  ASSERT_TRUE(microsim::sim::readRecording(rec.toStdString(), recorded).ok());
  EXPECT_EQ(recorded.scene, microsim::sim::recordScene(scene.toStdString()));
  EXPECT_EQ(recorded.metadata, R"({"script":"stitch"})");

  // no --scene: the same scene, the same hash
  r = runCli({QStringLiteral("run"), QStringLiteral("--input"), rec, QStringLiteral("--json"), second});
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();
  EXPECT_EQ(readRunJson(first).value(QStringLiteral("steps")).toInt(), 120);
  EXPECT_EQ(readRunJson(second).value(QStringLiteral("steps")).toInt(), 120);
  EXPECT_TRUE(r.out.startsWith(QStringLiteral("scene  ") + scene + QLatin1Char('\n'))) << r.out.toStdString();
  EXPECT_EQ(readRunJson(second).value(QStringLiteral("scene")).toString(), scene);
  EXPECT_EQ(readRunJson(first).value(QStringLiteral("hash")).toString(),
            readRunJson(second).value(QStringLiteral("hash")).toString());

  // the scene gone: named, with where it was looked for; --scene still runs it
  ASSERT_TRUE(QFile::remove(scene));
  r = runCli({QStringLiteral("run"), QStringLiteral("--input"), rec});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_TRUE(r.err.contains(QStringLiteral("microsim-cli run: the recording was made on the scene %1").arg(scene)))
      << r.err.toStdString();
  EXPECT_TRUE(r.err.contains(QStringLiteral("give --scene FILE"))) << r.err.toStdString();
  const QString third = dir.filePath(QStringLiteral("third.json"));
  r = runCli({QStringLiteral("run"), QStringLiteral("--input"), rec, QStringLiteral("--scene"), kShippedScene,
              QStringLiteral("--json"), third});
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();
  EXPECT_EQ(readRunJson(third).value(QStringLiteral("scene")).toString(), kShippedScene);
  EXPECT_EQ(readRunJson(third).value(QStringLiteral("hash")).toString(),
            readRunJson(first).value(QStringLiteral("hash")).toString());

  // the shipped stitch (format version 1) names none: only --scene can
  r = runCli({QStringLiteral("run"), QStringLiteral("--input"), kShippedStitch});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(r.err.contains(QStringLiteral("microsim-cli run: the recording names no scene: give --scene FILE")))
      << r.err.toStdString();
}

TEST(RunCommand, ADamagedRecordingFailsWithAClearMessage) {
  QTemporaryDir dir;
  QFile in(kShippedStitch);
  ASSERT_TRUE(in.open(QIODevice::ReadOnly));
  QByteArray bytes = in.readAll();
  bytes[bytes.size() / 2] = static_cast<char>(bytes[bytes.size() / 2] ^ 0x40);
  const QString damaged = dir.filePath(QStringLiteral("damaged.msrec"));
  QFile out(damaged);
  ASSERT_TRUE(out.open(QIODevice::WriteOnly));
  out.write(bytes);
  out.close();
  const CliRun r = runCli({QStringLiteral("run"), QStringLiteral("--scene"), kShippedScene, QStringLiteral("--input"), damaged});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_TRUE(r.err.contains(damaged)) << r.err.toStdString();
  EXPECT_TRUE(r.err.contains(QStringLiteral("damaged recording"))) << r.err.toStdString();
}

TEST(RunCommand, ABrokenSceneOrAMissingMeshNamesTheFileAndField) {
  QTemporaryDir dir;
  const QString scene = dir.filePath(QStringLiteral("s.json"));
  QFile f(scene);
  ASSERT_TRUE(f.open(QIODevice::WriteOnly));
  f.write("{\"objects\": [{\"type\": \"severed-vessel\"}],\n"
          " \"tools\": {\"forceps\": [{\"hand\": \"left\", \"mesh\": \"missing.obj\"}]}}\n");
  f.close();
  const CliRun r = runCli({QStringLiteral("run"), QStringLiteral("--scene"), scene});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_TRUE(r.err.contains(scene + QStringLiteral(":2:"))) << r.err.toStdString();
  EXPECT_TRUE(r.err.contains(QStringLiteral("tools.forceps[0].mesh"))) << r.err.toStdString();
  const CliRun usage = runCli({QStringLiteral("run")});
  EXPECT_EQ(usage.exitCode, 2);
}

}  // namespace
