// A process killed (SIGKILL) in the middle of writing, through the real microsim-cli:
// `track --record` keeps every sample it had received, readable as Truncated; a killed
// `db backup` leaves the history as it was and no file under the backup's name.
// `calibrate pivot` on such a cut stream uses its complete samples and warns.
// (A killed graded attempt: tests/assessment/storage/history_crash_test.cpp.)
#include "support/cli_runner.h"

#include "app/calibration/synthetic_pivot_stream.h"
#include "app/tracking/igtl_test_server.h"
#include "microsim/assessment/scoring/score.h"
#include "microsim/assessment/storage/attempt_store.h"
#include "microsim/assessment/storage/history_database.h"
#include "microsim/assessment/storage/people_store.h"
#include "microsim/assessment/storage/score_store.h"
#include "tracking/pose_stream.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>
#include <QThread>

#include <gtest/gtest.h>


namespace {

using microsim::assessment::AttemptMode;
using microsim::assessment::AttemptScore;
using microsim::assessment::HistoryDatabase;
using microsim::assessment::Role;
namespace tracking = microsim::tracking;

// microsim-cli started as a user would, left running
void startCli(QProcess& p, const QStringList& args) {
  QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
  env.insert(QStringLiteral("LC_ALL"), QStringLiteral("C"));
  p.setProcessEnvironment(env);
  p.start(QStringLiteral(MICROSIM_CLI_PATH), args);
  ASSERT_TRUE(p.waitForStarted());
}

std::size_t samplesIn(const QString& path) {
  tracking::PoseStream s;
  tracking::readPoseStream(path, s);
  return s.samples.size();
}

TEST(Killed, TrackRecordKeepsEveryReceivedSampleReadableAsTruncated) {
  constexpr int kPoses = 60;
  std::vector<Eigen::Matrix4d> poses;
  poses.reserve(kPoses);
  for (int i = 0; i < kPoses; ++i)
    poses.push_back(microsim::testing::floatPose(0.01 * i, {0, 0, 1}, {1.0 * i, 2.0, -3.0}));
  const microsim::testing::PoseStreamingServer server(std::move(poses));  // the link stays up until the kill
  ASSERT_GT(server.port(), 0);
  const std::vector<Eigen::Matrix4d>& sent = server.poses();

  QTemporaryDir dir;
  const QString file = dir.filePath(QStringLiteral("stream.json"));
  QProcess track;
  startCli(track, {QStringLiteral("track"), QStringLiteral("--igtl"), QStringLiteral("127.0.0.1:%1").arg(server.port()),
                   QStringLiteral("--duration"), QStringLiteral("600"), QStringLiteral("--record"), file});
  // every pose on disk while the process still runs, then the kill
  ASSERT_TRUE(QTest::qWaitFor([&] { return samplesIn(file) == sent.size(); }, 30000)) << samplesIn(file);
  ASSERT_EQ(track.state(), QProcess::Running);
  track.kill();
  ASSERT_TRUE(track.waitForFinished());
  EXPECT_EQ(track.exitStatus(), QProcess::CrashExit);

  tracking::PoseStream back;
  const tracking::PoseStreamStatus status = tracking::readPoseStream(file, back);
  EXPECT_EQ(status.error, tracking::PoseStreamError::Truncated);
  ASSERT_EQ(back.samples.size(), sent.size());
  for (std::size_t i = 0; i < sent.size(); ++i) {
    const auto& p = std::get<tracking::RawPose>(back.samples[i]);
    EXPECT_EQ(p.device, "Stylus");
    EXPECT_TRUE(p.matrix.isApprox(sent[i], 1e-6)) << i;
  }

  // cut inside the last line too: the complete lines are kept
  QFile f(file);
  ASSERT_TRUE(f.open(QIODevice::ReadOnly));
  QByteArray bytes = f.readAll();
  bytes.chop(7);
  EXPECT_EQ(tracking::decodePoseStream(bytes, back).error, tracking::PoseStreamError::Truncated);
  EXPECT_EQ(back.samples.size(), sent.size() - 1);
}

TEST(Killed, BackupLeavesTheHistoryAndNoFileUnderTheBackupsName) {
  QTemporaryDir dir;
  const QString db = dir.filePath(QStringLiteral("history.sqlite"));
  constexpr int kAttempts = 40;
  {
    // big enough (40 recordings of 1 MB) that the copy takes a while
    HistoryDatabase history;
    ASSERT_TRUE(history.open(db).ok());
    const qint64 trainee = microsim::assessment::PeopleStore(history).addTrainee(QStringLiteral("Ada")).value_or(0);
    QByteArray recording(1 << 20, '\0');
    for (int i = 0; i < kAttempts; ++i) {
      for (qsizetype k = 0; k < recording.size(); k += 4096) recording[k] = static_cast<char>(i + k);
      const qint64 id = microsim::assessment::AttemptStore(history).begin(trainee, QStringLiteral("01_orientation"), AttemptMode::Test).value_or(0);
      AttemptScore score;
      score.score = i;
      score.rubricId = "r";
      ASSERT_TRUE(microsim::assessment::ScoreStore(history).finish(id, score, recording));
    }
  }
  const QString backup = dir.filePath(QStringLiteral("backup.sqlite"));
  const QString partial = backup + QStringLiteral(".part");

  QProcess p;
  startCli(p, {QStringLiteral("db"), QStringLiteral("backup"), backup, QStringLiteral("--db"), db});
  // killed as soon as the copy has begun
  while (!QFile::exists(partial) && p.state() == QProcess::Running) QThread::yieldCurrentThread();
  ASSERT_EQ(p.state(), QProcess::Running) << "the backup finished before it could be killed";
  p.kill();
  ASSERT_TRUE(p.waitForFinished());
  EXPECT_FALSE(QFile::exists(backup));

  // the history keeps every attempt, and the next backup replaces the stale side file
  const microsim::testing::CliRun again =
      microsim::testing::runCli({QStringLiteral("db"), QStringLiteral("backup"), backup, QStringLiteral("--db"), db});
  ASSERT_EQ(again.exitCode, 0) << again.err.toStdString();
  EXPECT_FALSE(QFile::exists(partial));
  for (const QString& path : {db, backup}) {
    HistoryDatabase history;
    ASSERT_TRUE(history.open(path).ok()) << path.toStdString();
    history.setPasswordIterations(1000);
    const qint64 ines = microsim::assessment::PeopleStore(history).addInstructor(QStringLiteral("Ines"), QStringLiteral("s3cret-enough")).value_or(0);
    const auto rows = microsim::assessment::AttemptStore(history).list({ines, Role::Instructor});
    ASSERT_EQ(rows.size(), kAttempts) << path.toStdString();
    EXPECT_EQ(rows.back().score.value_or(-1.0), kAttempts - 1.0);
  }
}

// what a `track --record` killed mid-stream leaves: the header and every flushed line, no end
QByteArray cutStream(const tracking::PoseStream& stream, std::size_t samples, int chopBytes) {
  const QTemporaryDir dir;
  const QString path = dir.filePath(QStringLiteral("cut.json"));
  {
    tracking::PoseStreamWriter writer;
    EXPECT_TRUE(writer.open(path).ok());
    for (std::size_t i = 0; i < samples; ++i) EXPECT_TRUE(writer.append(stream.samples[i]).ok());
    // destroyed without finish(), as by the kill
  }
  QFile f(path);
  EXPECT_TRUE(f.open(QIODevice::ReadOnly));
  QByteArray bytes = f.readAll();
  bytes.chop(chopBytes);
  return bytes;
}

TEST(Killed, ACutShortTrackerStreamCalibratesThePivotFromItsCompleteSamplesWithAWarning) {
  const Eigen::Vector3d tip(-1.0, 2.5, 151.0);
  const Eigen::Vector3d pivot(30.0, 12.0, -200.0);
  const tracking::PoseStream stream = microsim::testing::pivotStream("Stylus", tip, pivot, 400, 35.0, 0.0);
  QTemporaryDir dir;
  const QString file = dir.filePath(QStringLiteral("stream.json"));
  const QString out = dir.filePath(QStringLiteral("tip.json"));
  const auto calibrate = [&](const QByteArray& bytes) {
    QFile f(file);
    EXPECT_TRUE(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    f.write(bytes);
    f.close();
    QFile::remove(out);
    return microsim::testing::runCli({QStringLiteral("calibrate"), QStringLiteral("pivot"), QStringLiteral("--input"), file,
                                      QStringLiteral("--json"), out});
  };
  const auto tipOffset = [&] {
    QFile f(out);
    EXPECT_TRUE(f.open(QIODevice::ReadOnly));
    return QJsonDocument::fromJson(f.readAll()).object();
  };

  // cut inside the 400th line: the 399 complete samples give the tip, with a warning naming the file
  microsim::testing::CliRun r = calibrate(cutStream(stream, 400, 9));
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString() << r.out.toStdString();
  EXPECT_TRUE(r.err.contains(QStringLiteral("warning: %1 was cut short").arg(file))) << r.err.toStdString();
  EXPECT_TRUE(r.err.contains(QStringLiteral("using its 399 complete sample(s)"))) << r.err.toStdString();
  QJsonObject result = tipOffset();
  EXPECT_EQ(result.value(QStringLiteral("status")).toString(), QStringLiteral("ok"));
  EXPECT_EQ(result.value(QStringLiteral("poses")).toInt(), 399);
  const QJsonArray t = result.value(QStringLiteral("tip_offset")).toArray();
  ASSERT_EQ(t.size(), 3);
  EXPECT_LE((Eigen::Vector3d(t.at(0).toDouble(), t.at(1).toDouble(), t.at(2).toDouble()) - tip).norm(), 0.01);

  // cut after whole lines (the kill between two samples): all of them
  r = calibrate(cutStream(stream, 300, 0));
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString() << r.out.toStdString();
  EXPECT_TRUE(r.err.contains(QStringLiteral("using its 300 complete sample(s)"))) << r.err.toStdString();
  EXPECT_EQ(tipOffset().value(QStringLiteral("poses")).toInt(), 300);

  // too few samples left for the fit: the usual refusal, and still the warning
  r = calibrate(cutStream(stream, 5, 0));
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_TRUE(r.err.contains(QStringLiteral("cut short"))) << r.err.toStdString();
  EXPECT_TRUE(r.out.contains(QStringLiteral("too_few_poses"))) << r.out.toStdString();
  r = calibrate(cutStream(stream, 0, 0));
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_TRUE(r.out.contains(QStringLiteral("too_few_poses"))) << r.out.toStdString() << r.err.toStdString();

  // the whole stream: no warning; garbage is still refused as before
  QByteArray whole = cutStream(stream, 400, 0);
  r = calibrate(whole + "]}\n");
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();
  EXPECT_FALSE(r.err.contains(QStringLiteral("cut short"))) << r.err.toStdString();
  EXPECT_EQ(tipOffset().value(QStringLiteral("poses")).toInt(), 400);
  r = calibrate(whole.mid(1));
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_TRUE(r.err.contains(QStringLiteral("is not a JSON object"))) << r.err.toStdString();
}

}  // namespace
