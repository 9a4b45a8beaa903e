// A full disk, as the user meets it through microsim-cli: every output path is /dev/full,
// where open() succeeds and every write fails with ENOSPC. Each command must say it could
// not write (exit code 1), never report success, and leave the history it read intact.
#include "support/cli_runner.h"

#include "app/tracking/igtl_test_server.h"
#include "tracking/pose_stream.h"

#include "microsim/assessment/storage/attempt_store.h"
#include "microsim/assessment/storage/history_database.h"
#include "microsim/assessment/storage/people_store.h"
#include "support/shipped_files.h"

#include <QFile>
#include <QProcess>
#include <QFileInfo>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <csignal>
#include <sys/resource.h>

namespace {

using microsim::assessment::AttemptMode;
using microsim::assessment::HistoryDatabase;
using microsim::assessment::Role;
using microsim::testing::CliRun;
using microsim::testing::runCli;

using microsim::testing::kShippedRubric;
using microsim::testing::kShippedScene;
using microsim::testing::kShippedStitch;
const QString kFull = QStringLiteral("/dev/full");

class DiskFull : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!QFile::exists(kFull)) GTEST_SKIP() << "no /dev/full on this system";
    // a writer that renames over its target, run as root, can leave a regular file there;
    // every test below would then fail for that reason rather than its own
    ASSERT_FALSE(QFileInfo(kFull).isFile())
        << "/dev/full is a regular file, not the device; as root restore it: rm /dev/full && mknod -m 666 /dev/full c 1 7";
  }

  // a history with a trainee, an instructor and one begun attempt
  QString makeHistory() {
    QString path = dir_.filePath(QStringLiteral("history.sqlite"));
    HistoryDatabase db;
    EXPECT_TRUE(db.open(path).ok());
    db.setPasswordIterations(1000);
    const qint64 trainee = microsim::assessment::PeopleStore(db).addTrainee(QStringLiteral("Ada")).value_or(0);
    EXPECT_TRUE(microsim::assessment::PeopleStore(db).addInstructor(QStringLiteral("Ines"), QStringLiteral("s3cret-enough")).has_value());
    EXPECT_TRUE(microsim::assessment::AttemptStore(db).begin(trainee, QStringLiteral("01_orientation"), AttemptMode::Test).has_value());
    return path;
  }

  QTemporaryDir dir_;
};

// the message names the path and the system's reason
void expectFullDiskError(const CliRun& r) {
  EXPECT_EQ(r.exitCode, 1) << r.out.toStdString() << r.err.toStdString();
  EXPECT_TRUE(r.err.contains(QStringLiteral("cannot write"))) << r.err.toStdString();
  EXPECT_TRUE(r.err.contains(kFull)) << r.err.toStdString();
}

TEST_F(DiskFull, JsonOutputOfEveryCommandIsAnError) {
  const QStringList commands[] = {
      {QStringLiteral("run"), QStringLiteral("--scene"), kShippedScene, QStringLiteral("--frames"), QStringLiteral("3"),
       QStringLiteral("--json"), kFull},
      {QStringLiteral("solve"), QStringLiteral("--lattice"), QStringLiteral("3"), QStringLiteral("--iterations"),
       QStringLiteral("5"), QStringLiteral("--json"), kFull},
      {QStringLiteral("export"), QStringLiteral("--lattice"), QStringLiteral("3"), QStringLiteral("--json"), kFull},
      {QStringLiteral("bench"), QStringLiteral("fig5"), QStringLiteral("--quick"), QStringLiteral("--json"), kFull},
      {QStringLiteral("bench"), QStringLiteral("fig5"), QStringLiteral("--quick"), QStringLiteral("--plot"), kFull},
  };
  for (const QStringList& args : commands) {
    SCOPED_TRACE(args.join(QLatin1Char(' ')).toStdString());
    expectFullDiskError(runCli(args));
  }
}

TEST_F(DiskFull, ScoreJsonIsAnErrorAndTheAttemptIsStillStored) {
  const QString db = makeHistory();
  const CliRun r = runCli({QStringLiteral("score"), QStringLiteral("--recording"), kShippedStitch, QStringLiteral("--rubric"),
                           kShippedRubric, QStringLiteral("--scene"), kShippedScene, QStringLiteral("--db"), db,
                           QStringLiteral("--trainee"), QStringLiteral("Ada"), QStringLiteral("--json"), kFull});
  expectFullDiskError(r);
  // the score went to the history before the JSON was attempted
  HistoryDatabase history;
  ASSERT_TRUE(history.open(db).ok());
  const qint64 ines = microsim::assessment::PeopleStore(history).verifyInstructor(QStringLiteral("Ines"), QStringLiteral("s3cret-enough")).value_or(0);
  const auto rows = microsim::assessment::AttemptStore(history).list({ines, Role::Instructor});
  ASSERT_EQ(rows.size(), 2);
  EXPECT_TRUE(rows.back().score.has_value());
}

TEST_F(DiskFull, RunRecordFailsBeforeTheFirstStep) {
  const CliRun r = runCli({QStringLiteral("run"), QStringLiteral("--scene"), kShippedScene, QStringLiteral("--frames"),
                           QStringLiteral("3"), QStringLiteral("--record"), kFull});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_TRUE(r.err.contains(QStringLiteral("cannot write the recording"))) << r.err.toStdString();
}

// A disk that fills while the stream is being recorded: the child's file-size limit
// (RLIMIT_FSIZE, with SIGXFSZ ignored) makes a write fail part-way through, as ENOSPC would.
TEST(DiskFillsMidStream, TrackRecordStopsWithAnErrorAndKeepsTheCompleteSamples) {
  constexpr int kPoses = 400;
  constexpr rlim_t kFileLimit = 4096;  // bytes: the header and some dozens of samples
  std::vector<Eigen::Matrix4d> poses;
  poses.reserve(kPoses);
  for (int i = 0; i < kPoses; ++i)
    poses.push_back(microsim::testing::floatPose(0.01 * i, {0, 0, 1}, {1.0 * i, 2.0, -3.0}));
  // the link stays up: the client must stop by itself
  const microsim::testing::PoseStreamingServer server(std::move(poses));
  ASSERT_GT(server.port(), 0);
  const std::vector<Eigen::Matrix4d>& sent = server.poses();

  QTemporaryDir dir;
  const QString file = dir.filePath(QStringLiteral("stream.json"));
  QProcess track;
  QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
  env.insert(QStringLiteral("LC_ALL"), QStringLiteral("C"));
  track.setProcessEnvironment(env);
  track.setChildProcessModifier([] {
    const rlimit limit{kFileLimit, kFileLimit};
    setrlimit(RLIMIT_FSIZE, &limit);
    signal(SIGXFSZ, SIG_IGN);  // a write past the limit fails with EFBIG instead of killing
  });
  track.start(QStringLiteral(MICROSIM_CLI_PATH),
              {QStringLiteral("track"), QStringLiteral("--igtl"), QStringLiteral("127.0.0.1:%1").arg(server.port()),
               QStringLiteral("--duration"), QStringLiteral("60"), QStringLiteral("--record"), file});
  ASSERT_TRUE(track.waitForFinished(60000));
  const QString err = QString::fromUtf8(track.readAllStandardError());
  EXPECT_EQ(track.exitStatus(), QProcess::NormalExit);
  EXPECT_EQ(track.exitCode(), 1) << err.toStdString();
  EXPECT_TRUE(err.contains(QStringLiteral("cannot write ") + file)) << err.toStdString();

  // what reached the disk is the stream's beginning, cut inside a line: every complete
  // sample is there, exactly as sent
  EXPECT_LE(QFileInfo(file).size(), static_cast<qint64>(kFileLimit));
  microsim::tracking::PoseStream back;
  EXPECT_EQ(microsim::tracking::readPoseStream(file, back).error, microsim::tracking::PoseStreamError::Truncated);
  ASSERT_GT(back.samples.size(), 5u);
  ASSERT_LT(back.samples.size(), sent.size());
  for (std::size_t i = 0; i < back.samples.size(); ++i)
    EXPECT_TRUE(std::get<microsim::tracking::RawPose>(back.samples[i]).matrix.isApprox(sent[i], 1e-6)) << i;
}

TEST_F(DiskFull, TrackRecordFailsBeforeConnecting) {
  // no server is needed: the stream's first line is flushed before the link opens
  const CliRun r = runCli({QStringLiteral("track"), QStringLiteral("--igtl"), QStringLiteral("127.0.0.1:1"),
                           QStringLiteral("--record"), kFull, QStringLiteral("--once")});
  expectFullDiskError(r);
  EXPECT_FALSE(r.err.contains(QStringLiteral("could not connect"))) << r.err.toStdString();
}

TEST_F(DiskFull, DbOutputsAreErrorsAndTheHistoryIsUnchanged) {
  const QString db = makeHistory();
  const QStringList on = {QStringLiteral("--db"), db};

  CliRun r = runCli(QStringList{QStringLiteral("db"), QStringLiteral("export-csv"), kFull, QStringLiteral("--instructor"),
                                QStringLiteral("Ines")} + on,
                    120000, "s3cret-enough\n");
  expectFullDiskError(r);
  EXPECT_FALSE(r.out.contains(QStringLiteral("wrote"))) << r.out.toStdString();

  r = runCli(QStringList{QStringLiteral("db"), QStringLiteral("list-trainees"), QStringLiteral("--json"), kFull} + on);
  expectFullDiskError(r);

  // /dev/full exists: backup never writes over an existing file
  r = runCli(QStringList{QStringLiteral("db"), QStringLiteral("backup"), kFull} + on);
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_TRUE(r.err.contains(QStringLiteral("/dev/full exists already; it was left untouched"))) << r.err.toStdString();

  HistoryDatabase history;
  ASSERT_TRUE(history.open(db).ok());
  EXPECT_EQ(microsim::assessment::PeopleStore(history).trainees().size(), 2);
  const qint64 ines = microsim::assessment::PeopleStore(history).verifyInstructor(QStringLiteral("Ines"), QStringLiteral("s3cret-enough")).value_or(0);
  EXPECT_EQ(microsim::assessment::AttemptStore(history).list({ines, Role::Instructor}).size(), 1);
}

}  // namespace
