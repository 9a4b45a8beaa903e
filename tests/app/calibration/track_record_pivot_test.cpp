// From the tracker to a tip offset without the GUI: `track --record` stores what a real
// OpenIGTLink server streams, `calibrate pivot --device` solves on that recording, and a
// ReplaySource plays it back pose for pose.
#include "support/cli_runner.h"

#include "app/calibration/synthetic_pivot_stream.h"
#include "app/tracking/igtl_test_server.h"
#include "tracking/replay_source.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSignalSpy>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace {

using microsim::testing::IgtlTestServer;
using microsim::testing::runCli;
namespace tracking = microsim::tracking;

TEST(TrackRecord, RecordedStreamCalibratesAndReplays) {
  const Eigen::Vector3d tip(-1.0, 2.5, 151.0);
  const Eigen::Vector3d pivot(30.0, 12.0, -200.0);
  const tracking::PoseStream sent = microsim::testing::pivotStream("Stylus", tip, pivot, 400, 35.0, 0.0);
  IgtlTestServer server;
  ASSERT_GT(server.port(), 0);
  server.run([&](IgtlTestServer& s) {
    if (!s.accept()) return;
    for (std::size_t i = 0; i < sent.samples.size(); ++i) {
      const auto& p = std::get<tracking::RawPose>(sent.samples[i]);
      s.send(microsim::testing::transformMessage(p.device, p.matrix, p.time));
      // NOLINTNEXTLINE(bugprone-integer-division): the grip steps up once every 50 poses
      if (i % 50 == 0) s.send(microsim::testing::sensorMessage("Grip", 0.1 * static_cast<double>(i / 50), p.time));
    }
    s.send(microsim::testing::transformMessage("Reference", microsim::testing::floatPose(0, {1, 0, 0}, {0, 0, 0}), 100.0));
    s.closeClient();
  });

  QTemporaryDir dir;
  const QString recording = dir.filePath(QStringLiteral("pivot.json"));
  const microsim::testing::CliRun track =
      runCli({QStringLiteral("track"), QStringLiteral("--igtl"), QStringLiteral("127.0.0.1:%1").arg(server.port()),
              QStringLiteral("--duration"), QStringLiteral("60"), QStringLiteral("--once"), QStringLiteral("--record"),
              recording});
  server.join();
  ASSERT_EQ(track.exitCode, 0) << track.err.toStdString();

  // the recording holds every accepted pose and channel value, in arrival order
  tracking::PoseStream stream;
  ASSERT_TRUE(tracking::readPoseStream(recording, stream).ok());
  ASSERT_EQ(stream.samples.size(), 400u + 8u + 1u);
  const auto& first = std::get<tracking::RawPose>(stream.samples[0]);
  EXPECT_EQ(first.device, "Stylus");
  EXPECT_TRUE(first.matrix.isApprox(std::get<tracking::RawPose>(sent.samples[0]).matrix, 1e-6));
  EXPECT_TRUE(std::holds_alternative<tracking::ChannelValue>(stream.samples[1]));

  // two devices: the pivot needs --device, then recovers the tip
  const QString out = dir.filePath(QStringLiteral("tip.json"));
  const microsim::testing::CliRun ambiguous =
      runCli({QStringLiteral("calibrate"), QStringLiteral("pivot"), QStringLiteral("--input"), recording});
  EXPECT_EQ(ambiguous.exitCode, 1);
  EXPECT_TRUE(ambiguous.err.contains(QStringLiteral("--device"))) << ambiguous.err.toStdString();
  const microsim::testing::CliRun calibrate =
      runCli({QStringLiteral("calibrate"), QStringLiteral("pivot"), QStringLiteral("--input"), recording,
              QStringLiteral("--device"), QStringLiteral("Stylus"), QStringLiteral("--json"), out});
  ASSERT_EQ(calibrate.exitCode, 0) << calibrate.err.toStdString() << calibrate.out.toStdString();
  QFile f(out);
  ASSERT_TRUE(f.open(QIODevice::ReadOnly));
  const QJsonObject result = QJsonDocument::fromJson(f.readAll()).object();
  const QJsonArray t = result.value(QStringLiteral("tip_offset")).toArray();
  ASSERT_EQ(t.size(), 3);
  EXPECT_LE((Eigen::Vector3d(t.at(0).toDouble(), t.at(1).toDouble(), t.at(2).toDouble()) - tip).norm(), 0.01);
  EXPECT_EQ(result.value(QStringLiteral("poses")).toInt(), 400);

  // the replay plays every recorded pose and value
  tracking::ReplayConfig config;
  config.pace = tracking::ReplayPace::AsFastAsPossible;
  tracking::ReplayFileStatus status;
  std::unique_ptr<tracking::ReplaySource> replay = tracking::openReplay(recording, config, status);
  ASSERT_TRUE(replay);
  QSignalSpy poses(replay.get(), &tracking::TrackerSource::poseAccepted);
  QSignalSpy values(replay.get(), &tracking::TrackerSource::channelAccepted);
  QSignalSpy finished(replay.get(), &tracking::ReplaySource::finished);
  replay->start();
  ASSERT_TRUE(finished.wait(10000));
  EXPECT_EQ(poses.count(), 401);
  EXPECT_EQ(values.count(), 8);
  EXPECT_EQ(replay->status().dropped(), 0u);
}

}  // namespace
