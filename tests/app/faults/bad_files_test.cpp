// Bad input files as the user meets them through microsim-cli: a folder where a file
// belongs, a file the user may not read, meshes assimp cannot read, recordings cut short
// or from a newer version. Each is a message naming the file and exit code 1 (a recording
// cut short replays its complete frames); none changes the file.
#include "support/cli_runner.h"

#include "lesson/lesson.h"
#include "microsim/sim/scene/recording.h"
#include "support/shipped_files.h"

#include <QFile>
#include <QProcess>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <unistd.h>

namespace {

using microsim::testing::CliRun;
using microsim::testing::runCli;

using microsim::testing::kShippedRubric;
using microsim::testing::kShippedScene;
using microsim::testing::kShippedStitch;

QByteArray readFaultFile(const QString& path) {
  QFile f(path);
  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

void write(const QString& path, const QByteArray& bytes) {
  QFile f(path);
  ASSERT_TRUE(f.open(QIODevice::WriteOnly));
  f.write(bytes);
}

// microsim-cli as an ordinary user: when the tests run as root, the child drops to
// nobody, since root reads files whatever their mode
CliRun runCliAsUser(const QStringList& args) {
  QProcess p;
  QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
  env.insert(QStringLiteral("LC_ALL"), QStringLiteral("C"));
  p.setProcessEnvironment(env);
  if (::geteuid() == 0) {
    p.setChildProcessModifier([] {
      if (::setgid(65534) != 0 || ::setuid(65534) != 0) ::_exit(97);
    });
  }
  p.start(QStringLiteral(MICROSIM_CLI_PATH), args);
  CliRun r;
  if (!p.waitForFinished(60000)) return r;
  r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2;
  r.out = QString::fromUtf8(p.readAllStandardOutput());
  r.err = QString::fromUtf8(p.readAllStandardError());
  return r;
}

void expectRefused(const CliRun& r, const QString& path, const QString& words) {
  EXPECT_EQ(r.exitCode, 1) << r.out.toStdString() << r.err.toStdString();
  EXPECT_TRUE(r.err.contains(path)) << r.err.toStdString();
  EXPECT_TRUE(r.err.contains(words)) << r.err.toStdString();
}

TEST(BadFiles, AFolderWhereAFileBelongsIsNamed) {
  QTemporaryDir dir;
  const QString folder = dir.path();
  expectRefused(runCli({QStringLiteral("run"), QStringLiteral("--scene"), folder}), folder,
                QStringLiteral("cannot open the scene file"));
  expectRefused(runCli({QStringLiteral("run"), QStringLiteral("--scene"), kShippedScene, QStringLiteral("--input"), folder}),
                folder, QStringLiteral("cannot open the recording"));
  expectRefused(runCli({QStringLiteral("score"), QStringLiteral("--recording"), kShippedStitch, QStringLiteral("--rubric"),
                        folder, QStringLiteral("--scene"), kShippedScene}),
                folder, QStringLiteral("cannot open the rubric file"));
  expectRefused(runCli({QStringLiteral("db"), QStringLiteral("migrate"), QStringLiteral("--db"), folder}), folder,
                QStringLiteral("cannot open"));
  expectRefused(runCli({QStringLiteral("calibrate"), QStringLiteral("pivot"), QStringLiteral("--input"), folder}),
                folder, QStringLiteral("cannot read"));
  // and as an output
  expectRefused(runCli({QStringLiteral("export"), QStringLiteral("--lattice"), QStringLiteral("2"),
                        QStringLiteral("--json"), folder}),
                folder, QStringLiteral("cannot write"));
  expectRefused(runCli({QStringLiteral("run"), QStringLiteral("--scene"), kShippedScene, QStringLiteral("--frames"),
                        QStringLiteral("2"), QStringLiteral("--record"), folder}),
                folder, QStringLiteral("cannot open the recording"));

  const auto lesson = microsim::lesson::loadLesson(folder);
  ASSERT_TRUE(std::holds_alternative<microsim::lesson::LessonError>(lesson));
  EXPECT_EQ(std::get<microsim::lesson::LessonError>(lesson).kind, microsim::lesson::LessonErrorKind::CannotOpen);
}

TEST(BadFiles, AnUnreadableFileIsNamedAndKeptAsItWas) {
  QTemporaryDir dir;
  // the folder open to all, each file readable by its owner only
  ASSERT_TRUE(QFile::setPermissions(dir.path(), QFileDevice::ReadOwner | QFileDevice::WriteOwner |
                                                    QFileDevice::ExeOwner | QFileDevice::ReadOther |
                                                    QFileDevice::ExeOther));
  const QString scene = dir.filePath(QStringLiteral("scene.json"));
  const QString recording = dir.filePath(QStringLiteral("stitch.msrec"));
  const QString rubric = dir.filePath(QStringLiteral("rubric.json"));
  ASSERT_TRUE(QFile::copy(kShippedScene, scene));
  ASSERT_TRUE(QFile::copy(kShippedStitch, recording));
  ASSERT_TRUE(QFile::copy(kShippedRubric, rubric));
  for (const QString& f : {scene, recording, rubric})
    ASSERT_TRUE(QFile::setPermissions(f, QFileDevice::ReadOwner | QFileDevice::WriteOwner));
  const QByteArray sceneBytes = readFaultFile(scene);

  expectRefused(runCliAsUser({QStringLiteral("run"), QStringLiteral("--scene"), scene}), scene,
                QStringLiteral("cannot open the scene file"));
  expectRefused(runCliAsUser({QStringLiteral("run"), QStringLiteral("--scene"), kShippedScene, QStringLiteral("--input"),
                              recording}),
                recording, QStringLiteral("cannot open the recording"));
  expectRefused(runCliAsUser({QStringLiteral("score"), QStringLiteral("--recording"), kShippedStitch,
                              QStringLiteral("--rubric"), rubric, QStringLiteral("--scene"), kShippedScene}),
                rubric, QStringLiteral("cannot open the rubric file"));
  EXPECT_EQ(readFaultFile(scene), sceneBytes);
}

TEST(BadFiles, MeshesAssimpCannotReadNameTheFieldAndTheReason) {
  QTemporaryDir dir;
  write(dir.filePath(QStringLiteral("garbage.obj")), QByteArray("this is not an obj\0\x01\xff garbage\n", 30));
  write(dir.filePath(QStringLiteral("garbage.stl")), QByteArray(300, '\x9c'));
  for (const QString& name : {QStringLiteral("garbage.obj"), QStringLiteral("garbage.stl")}) {
    const QString scene = dir.filePath(name + QStringLiteral(".json"));
    write(scene, QStringLiteral(R"({"objects": [{"type": "surface-mesh", "file": "%1"}]})").arg(name).toUtf8());
    const CliRun r = runCli({QStringLiteral("solve"), QStringLiteral("--scene"), scene, QStringLiteral("--iterations"),
                             QStringLiteral("3")});
    SCOPED_TRACE(name.toStdString());
    expectRefused(r, scene, QStringLiteral("cannot import the surface mesh (unreadable"));
    EXPECT_TRUE(r.err.contains(QStringLiteral("objects[0].file"))) << r.err.toStdString();
  }
}

TEST(BadFiles, ARecordingCutShortReplaysItsFramesAndANewerOneIsRefused) {
  QTemporaryDir dir;
  const QByteArray good = readFaultFile(kShippedStitch);
  ASSERT_GT(good.size(), 1000);

  const QString cut = dir.filePath(QStringLiteral("cut.msrec"));
  write(cut, good.left(good.size() * 2 / 3));
  CliRun r = runCli({QStringLiteral("run"), QStringLiteral("--scene"), kShippedScene, QStringLiteral("--input"), cut});
  EXPECT_EQ(r.exitCode, 0) << r.err.toStdString();
  EXPECT_TRUE(r.err.contains(QStringLiteral("unfinished recording"))) << r.err.toStdString();
  EXPECT_TRUE(r.err.contains(QStringLiteral("complete frame"))) << r.err.toStdString();

  QByteArray newer = good;
  newer[8] = static_cast<char>(microsim::sim::kRecordingVersion + 1);
  const QString future = dir.filePath(QStringLiteral("newer.msrec"));
  write(future, newer);
  r = runCli({QStringLiteral("run"), QStringLiteral("--scene"), kShippedScene, QStringLiteral("--input"), future});
  expectRefused(r, future, QStringLiteral("recording from a newer version"));
  EXPECT_EQ(readFaultFile(future), newer);
}

}  // namespace
