// `microsim-cli track` as a user runs it, against a real OpenIGTLink server in the test:
// exactly the valid poses sent are reported, the invalid ones counted by reason.
#include "support/cli_runner.h"

#include "app/tracking/igtl_test_server.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <limits>

namespace {

using microsim::testing::floatPose;
using microsim::testing::IgtlTestServer;
using microsim::testing::runCli;

TEST(TrackCommand, ReportsTheValidPosesAndCountsTheInvalidOnes) {
  IgtlTestServer server;
  ASSERT_GT(server.port(), 0);
  const Eigen::Matrix4d last = floatPose(0.25, {0, 1, 0}, {12.5, -3, 40});
  server.run([&](IgtlTestServer& s) {
    if (!s.accept()) return;
    // 50 poses of the stylus at 100 Hz, 20 of the reference at 20 Hz
    for (int i = 0; i < 50; ++i) {
      const Eigen::Matrix4d m = i == 49 ? last : floatPose(0.005 * i, {0, 1, 0}, {0.25 * i, -3, 40});
      s.send(microsim::testing::transformMessage("Stylus", m, 100.0 + 0.01 * i));
    }
    for (int i = 0; i < 20; ++i)
      s.send(microsim::testing::transformMessage("Reference", floatPose(0, {1, 0, 0}, {0, 0, 0}), 100.0 + 0.05 * i));
    // invalid: a NaN, a jump, a step back in time, a broken CRC, an unknown type
    Eigen::Matrix4d nan = last;
    nan(2, 3) = std::numeric_limits<double>::quiet_NaN();
    s.send(microsim::testing::transformMessage("Stylus", nan, 100.5));
    s.send(microsim::testing::transformMessage("Stylus", floatPose(0, {1, 0, 0}, {900, 0, 0}), 100.5));
    s.send(microsim::testing::transformMessage("Stylus", last, 99.0));
    const std::vector<std::uint8_t> good = microsim::testing::packed(microsim::testing::transformMessage("Stylus", last, 100.6));
    s.send(microsim::testing::rawMessage("TRANSFORM", "Stylus", 100.6,
                                         std::vector<std::uint8_t>(good.begin() + 58, good.end()), true));
    s.send(microsim::testing::rawMessage("STRING", "Note", 100.6, {0, 3, 0, 2, 'h', 'i'}));
    s.closeClient();
  });

  QTemporaryDir dir;
  const QString out = dir.filePath(QStringLiteral("track.json"));
  const microsim::testing::CliRun r =
      runCli({QStringLiteral("track"), QStringLiteral("--igtl"), QStringLiteral("127.0.0.1:%1").arg(server.port()),
              QStringLiteral("--duration"), QStringLiteral("60"), QStringLiteral("--once"), QStringLiteral("--json"), out});
  server.join();
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();
  EXPECT_TRUE(r.out.contains(QStringLiteral("Stylus"))) << r.out.toStdString();

  QFile f(out);
  ASSERT_TRUE(f.open(QIODevice::ReadOnly));
  const QJsonObject root = QJsonDocument::fromJson(f.readAll()).object();
  const QJsonObject devices = root.value(QStringLiteral("devices")).toObject();
  ASSERT_EQ(devices.size(), 2);
  const QJsonObject stylus = devices.value(QStringLiteral("Stylus")).toObject();
  EXPECT_EQ(stylus.value(QStringLiteral("received")).toInt(), 50);
  EXPECT_NEAR(stylus.value(QStringLiteral("rate_hz")).toDouble(), 100.0, 1e-3);
  const QJsonArray lastJson = stylus.value(QStringLiteral("last")).toArray();
  ASSERT_EQ(lastJson.size(), 16);
  for (int k = 0; k < 16; ++k) EXPECT_EQ(lastJson.at(k).toDouble(), last(k / 4, k % 4)) << k;
  const QJsonObject reference = devices.value(QStringLiteral("Reference")).toObject();
  EXPECT_EQ(reference.value(QStringLiteral("received")).toInt(), 20);
  EXPECT_NEAR(reference.value(QStringLiteral("rate_hz")).toDouble(), 20.0, 1e-3);

  const QJsonObject rejected = root.value(QStringLiteral("rejected")).toObject();
  EXPECT_EQ(rejected.value(QStringLiteral("count")).toInt(), 5);
  const QJsonObject reasons = rejected.value(QStringLiteral("reasons")).toObject();
  for (const char* key : {"non_finite", "too_fast", "time_backwards", "bad_crc", "unknown_type"})
    EXPECT_EQ(reasons.value(QLatin1String(key)).toInt(), 1) << key;
  EXPECT_EQ(reasons.value(QStringLiteral("truncated")).toInt(), 0);
  EXPECT_EQ(root.value(QStringLiteral("connections")).toInt(), 1);
}

TEST(TrackCommand, FailsCleanlyWhenNoServerAnswersAndOnABadAddress) {
  quint16 port = 0;
  {
    IgtlTestServer probe;
    port = static_cast<quint16>(probe.port());
  }
  const microsim::testing::CliRun refused =
      runCli({QStringLiteral("track"), QStringLiteral("--igtl"), QStringLiteral("127.0.0.1:%1").arg(port),
              QStringLiteral("--once"), QStringLiteral("--duration"), QStringLiteral("30")});
  EXPECT_EQ(refused.exitCode, 1);
  EXPECT_TRUE(refused.err.contains(QStringLiteral("could not connect"))) << refused.err.toStdString();

  const microsim::testing::CliRun usage =
      runCli({QStringLiteral("track"), QStringLiteral("--igtl"), QStringLiteral("host:notaport")});
  EXPECT_EQ(usage.exitCode, 2);
}

}  // namespace
