// The OpenIGTLink client against a real igtl::ServerSocket on loopback: known poses arrive
// exactly, every kind of garbage is refused and counted by reason, and the link survives a
// disconnect (the client reconnects and reads on).
#include "tracking/igtl_client.h"

#include "app/tracking/igtl_test_server.h"

#include <QSignalSpy>
#include <QTest>

#include <gtest/gtest.h>

#include <limits>

namespace microsim::tracking {
namespace {

using testing::floatPose;
using testing::igtlTime;
using testing::IgtlTestServer;
using testing::packed;
using testing::rawMessage;

constexpr int kWaitMs = 20000;

struct Received {
  std::vector<RawPose> poses;
  std::vector<ChannelValue> channels;
  std::vector<sim::InputFrame> frames;
  int linkDowns = 0;
};

void record(IgtlClient& client, QObject& context, Received& r) {
  QObject::connect(&client, &TrackerSource::poseAccepted, &context, [&r](const RawPose& p) { r.poses.push_back(p); });
  QObject::connect(&client, &TrackerSource::channelAccepted, &context,
                   [&r](const ChannelValue& v) { r.channels.push_back(v); });
  QObject::connect(&client, &TrackerSource::frameReady, &context,
                   [&r](const sim::InputFrame& f) { r.frames.push_back(f); });
  QObject::connect(&client, &TrackerSource::linkDown, &context, [&r] { ++r.linkDowns; });
}

TEST(IgtlClient, ReceivesPosesExactlyRefusesGarbageAndSurvivesADisconnect) {
  IgtlTestServer server;
  ASSERT_GT(server.port(), 0);

  // what the server will send: a slow walk of the left tool, the right tool, a grip value
  std::vector<RawPose> expected;
  expected.reserve(6);
  for (int i = 0; i < 5; ++i)
    expected.push_back({"Left", igtlTime(10.0 + 0.01 * i), floatPose(0.1 * i, {0, 0, 1}, {1.0 * i, 2, 3}), true});
  const Eigen::Matrix4d right = floatPose(-0.5, {1, 1, 0}, {-20, 5.5, 30});
  expected.push_back({"Right", igtlTime(10.05), right, true});
  const RawPose lastLeft{"Left", igtlTime(10.2), floatPose(0.5, {0, 0, 1}, {6, 2, 3}), true};
  std::vector<RawPose> afterReconnect;
  afterReconnect.reserve(3);
  for (int i = 0; i < 3; ++i)
    afterReconnect.push_back({"Left", igtlTime(0.5 + 0.01 * i), floatPose(0.0, {0, 0, 1}, {7.0 + i, 2, 3}), true});

  server.run([&](IgtlTestServer& s) {
    if (!s.accept()) return;
    for (const RawPose& p : expected) s.send(testing::transformMessage(p.device, p.matrix, p.time));
    s.send(testing::sensorMessage("LeftGrip", 75.0, 10.06));

    // garbage, one of each kind
    const std::vector<std::uint8_t> good = packed(testing::transformMessage("Left", lastLeft.matrix, 10.2));
    const std::vector<std::uint8_t> body(good.begin() + tracking::kIgtlHeaderSize, good.end());
    s.send(rawMessage("TRANSFORM", "Left", 10.1, body, /*breakCrc=*/true));
    s.send(rawMessage("TRANSFORM", "Left", 10.1, std::vector<std::uint8_t>(body.begin(), body.begin() + 36)));
    s.send(rawMessage("STATUS", "Left", 10.1, {0, 1, 2, 3}));
    Eigen::Matrix4d nan = lastLeft.matrix;
    nan(1, 3) = std::numeric_limits<double>::quiet_NaN();
    s.send(testing::transformMessage("Left", nan, 10.1));
    Eigen::Matrix4d skew = lastLeft.matrix;
    skew(0, 1) += 0.2;
    s.send(testing::transformMessage("Left", skew, 10.1));
    s.send(testing::transformMessage("Left", floatPose(0.4, {0, 0, 1}, {500, 2, 3}), 10.1));  // 500 mm in 60 ms
    s.send(testing::transformMessage("Left", lastLeft.matrix, 10.0));                        // before 10.04
    s.send(std::vector<std::uint8_t>(64, 0xee));                                              // not OpenIGTLink
    s.send(good);                                                                             // resynchronised
    s.send(std::vector<std::uint8_t>(good.begin(), good.begin() + 70));                       // cut short
    s.closeClient();

    // the client comes back; the server's clock restarted
    if (!s.accept()) return;
    for (const RawPose& p : afterReconnect) s.send(testing::transformMessage(p.device, p.matrix, p.time));
  });

  IgtlClientConfig config;
  config.port = static_cast<quint16>(server.port());
  config.limits.maxSpeed = 1000.0;
  config.reconnectInitialMs = 50;
  config.mapping.hands[0] = HandMapping{"Left", sim::Instrument::Forceps, "LeftGrip", 0.0, 100.0};
  config.mapping.hands[1] = HandMapping{"Right", sim::Instrument::NeedleHolder, "", 0.0, 1.0};
  IgtlClient client(config);
  QObject context;
  Received r;
  record(client, context, r);
  client.start();

  const std::size_t total = expected.size() + 1 + afterReconnect.size();
  ASSERT_TRUE(QTest::qWaitFor([&] { return r.poses.size() >= total; }, kWaitMs)) << r.poses.size();
  client.stop();
  QCoreApplication::sendPostedEvents(&context);
  server.join();

  // the valid poses, exactly, in order
  std::vector<RawPose> all = expected;
  all.push_back(lastLeft);
  all.insert(all.end(), afterReconnect.begin(), afterReconnect.end());
  ASSERT_EQ(r.poses.size(), all.size());
  for (std::size_t i = 0; i < all.size(); ++i) EXPECT_EQ(r.poses[i], all[i]) << i;
  ASSERT_EQ(r.channels.size(), 1u);
  EXPECT_EQ(r.channels[0], (ChannelValue{"LeftGrip", igtlTime(10.06), 75.0}));

  // every refusal counted by its reason
  const TrackerStatus status = client.status();
  EXPECT_EQ(status.connections, 2u);
  EXPECT_EQ(status.accepted, all.size());
  EXPECT_EQ(status.rejected[Rejection::BadCrc], 1u);
  EXPECT_EQ(status.rejected[Rejection::WrongBodySize], 1u);
  EXPECT_EQ(status.rejected[Rejection::UnknownType], 1u);
  EXPECT_EQ(status.rejected[Rejection::NonFinite], 1u);
  EXPECT_EQ(status.rejected[Rejection::NotOrthonormal], 1u);
  EXPECT_EQ(status.rejected[Rejection::TooFast], 1u);
  EXPECT_EQ(status.rejected[Rejection::TimeBackwards], 1u);
  EXPECT_EQ(status.rejected[Rejection::BadHeader], 1u);
  EXPECT_EQ(status.rejected[Rejection::Truncated], 1u);
  EXPECT_EQ(status.rejected[Rejection::InvalidFrame], 0u);
  EXPECT_EQ(status.dropped(), 9u);
  EXPECT_GE(r.linkDowns, 1);

  // frames: every mapped pose and the grip, plus the hands lost at the disconnect; time never goes back
  ASSERT_EQ(r.frames.size(), 5u + 1u + 1u + 1u + 1u + 3u);
  for (std::size_t i = 1; i < r.frames.size(); ++i) EXPECT_GE(r.frames[i].time, r.frames[i - 1].time);
  const sim::InputFrame& beforeLoss = r.frames[7];
  EXPECT_EQ(beforeLoss.hand(sim::Hand::Left).position, Eigen::Vector3d(lastLeft.matrix.topRightCorner<3, 1>()));
  EXPECT_EQ(beforeLoss.hand(sim::Hand::Left).closure, 0.75);
  EXPECT_EQ(beforeLoss.hand(sim::Hand::Right).position, Eigen::Vector3d(right.topRightCorner<3, 1>()));
  EXPECT_TRUE(beforeLoss.hand(sim::Hand::Right).tracked);
  EXPECT_FALSE(r.frames[8].hand(sim::Hand::Left).tracked);
  EXPECT_TRUE(r.frames.back().hand(sim::Hand::Left).tracked);
  EXPECT_EQ(r.frames.back().hand(sim::Hand::Left).position, Eigen::Vector3d(9, 2, 3));
}

TEST(IgtlClient, RetriesARefusedConnectionUntilTheServerAppears) {
  // a port that is free now: the first attempts are refused
  quint16 port = 0;
  {
    IgtlTestServer probe;
    port = static_cast<quint16>(probe.port());
  }
  IgtlClientConfig config;
  config.port = port;
  config.reconnectInitialMs = 20;
  config.reconnectMaxMs = 200;
  IgtlClient client(config);
  QObject context;
  Received r;
  record(client, context, r);
  client.start();
  ASSERT_TRUE(QTest::qWaitFor([&] { return r.linkDowns >= 2; }, kWaitMs));
  EXPECT_FALSE(client.status().connected);
  EXPECT_FALSE(client.status().lastError.isEmpty());
  client.stop();
  EXPECT_EQ(client.status().connections, 0u);
}

}  // namespace
}  // namespace microsim::tracking
