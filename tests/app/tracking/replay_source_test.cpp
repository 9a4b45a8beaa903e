// ReplaySource plays raw tracker streams through the same gate as a live link, and
// simulation recordings frame by frame; files are recognised by content.
#include "tracking/replay_source.h"

#include "app/calibration/synthetic_pivot_stream.h"

#include "microsim/sim/scene/recording.h"

#include <QCoreApplication>
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <limits>

namespace microsim::tracking {
namespace {

ReplayConfig fastConfig() {
  ReplayConfig c;
  c.pace = ReplayPace::AsFastAsPossible;
  c.batch = 16;
  c.mapping.hands[0].device = "Stylus";
  c.mapping.hands[0].closureChannel = "Grip";
  c.mapping.hands[0].closureOpen = 10.0;
  c.mapping.hands[0].closureClosed = 20.0;
  return c;
}

TEST(ReplaySource, PlaysAStreamThroughTheGateAndTheMapping) {
  PoseStream stream = testing::pivotStream("Stylus", {0, 0, 150}, {10, 20, 30}, 100, 20.0, 0.0);
  // garbage the gate refuses: NaN, a jump, and an unmapped device that still counts as a pose
  RawPose nan = std::get<RawPose>(stream.samples[50]);
  nan.matrix(0, 3) = std::numeric_limits<double>::quiet_NaN();
  stream.samples.insert(stream.samples.begin() + 51, nan);
  RawPose jump = std::get<RawPose>(stream.samples[60]);
  jump.matrix(0, 3) += 500.0;
  stream.samples.insert(stream.samples.begin() + 61, jump);
  RawPose other = std::get<RawPose>(stream.samples[10]);
  other.device = "Reference";
  stream.samples.insert(stream.samples.begin() + 11, other);
  stream.samples.emplace_back(ChannelValue{"Grip", 102.0, 15.0});

  ReplaySource source(stream, fastConfig());
  QSignalSpy finished(&source, &ReplaySource::finished);
  QSignalSpy poses(&source, &TrackerSource::poseAccepted);
  QSignalSpy frames(&source, &TrackerSource::frameReady);
  QSignalSpy refused(&source, &TrackerSource::rejected);
  source.start();
  ASSERT_TRUE(finished.wait(10000));

  EXPECT_EQ(poses.count(), 101);  // 100 stylus + 1 reference
  EXPECT_EQ(frames.count(), 101);  // 100 stylus poses + the grip value
  EXPECT_EQ(refused.count(), 2);
  const TrackerStatus status = source.status();
  EXPECT_FALSE(status.connected);
  EXPECT_EQ(status.accepted, 101u);
  EXPECT_EQ(status.rejected[Rejection::NonFinite], 1u);
  EXPECT_EQ(status.rejected[Rejection::TooFast], 1u);

  // frames are stamped from the first sample; the last carries the mapped closure
  const auto first = frames.first().at(0).value<sim::InputFrame>();
  const auto last = frames.last().at(0).value<sim::InputFrame>();
  EXPECT_DOUBLE_EQ(first.time, 0.0);
  EXPECT_NEAR(last.time, 2.0, 1e-9);
  EXPECT_TRUE(last.hands[0].tracked);
  EXPECT_DOUBLE_EQ(last.hands[0].closure, 0.5);
  const RawPose lastPose = std::get<RawPose>(stream.samples[102]);
  EXPECT_TRUE(last.hands[0].position.isApprox(lastPose.matrix.topRightCorner<3, 1>()));
}

TEST(ReplaySource, RealTimeKeepsTheOrderAndFinishes) {
  const PoseStream stream = testing::pivotStream("Stylus", {0, 0, 150}, {0, 0, 0}, 20, 20.0, 0.0);
  ReplayConfig config = fastConfig();
  config.pace = ReplayPace::RealTime;
  ReplaySource source(stream, config);
  QSignalSpy finished(&source, &ReplaySource::finished);
  QSignalSpy poses(&source, &TrackerSource::poseAccepted);
  source.start();
  ASSERT_TRUE(finished.wait(10000));
  ASSERT_EQ(poses.count(), 20);
  for (int i = 0; i < 20; ++i)
    EXPECT_EQ(poses.at(i).at(0).value<RawPose>(), std::get<RawPose>(stream.samples[static_cast<std::size_t>(i)]));
}

TEST(ReplaySource, StopEndsTheSignals) {
  const PoseStream stream = testing::pivotStream("Stylus", {0, 0, 150}, {0, 0, 0}, 200, 20.0, 0.0);
  ReplaySource source(stream, fastConfig());
  QSignalSpy poses(&source, &TrackerSource::poseAccepted);
  QObject::connect(&source, &TrackerSource::poseAccepted, &source, [&source] {
    if (source.played() == 40) source.stop();
  });
  QSignalSpy finished(&source, &ReplaySource::finished);
  source.start();
  for (int i = 0; i < 50; ++i) QCoreApplication::processEvents();
  EXPECT_EQ(finished.count(), 0);
  EXPECT_EQ(poses.count(), 40);
  EXPECT_FALSE(source.status().connected);
}

TEST(ReplaySource, OpensRecordingsAndStreamsByContent) {
  QTemporaryDir dir;

  // a simulation recording
  sim::Recording recording;
  for (int i = 0; i < 5; ++i) {
    sim::InputFrame f;
    f.time = 1.0 + 0.01 * i;
    f.hands[1].tracked = true;
    f.hands[1].position = Eigen::Vector3d(i, 0, 0);
    recording.frames.push_back(f);
  }
  const std::vector<std::uint8_t> bytes = sim::encodeRecording(recording);
  const QString recPath = dir.filePath(QStringLiteral("a.msrec"));
  {
    QFile f(recPath);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(reinterpret_cast<const char*>(bytes.data()), static_cast<qint64>(bytes.size()));
  }
  ReplayFileStatus status;
  std::unique_ptr<ReplaySource> rec = openReplay(recPath, fastConfig(), status);
  ASSERT_TRUE(rec) << static_cast<int>(status.error);
  QSignalSpy frames(rec.get(), &TrackerSource::frameReady);
  QSignalSpy finished(rec.get(), &ReplaySource::finished);
  rec->start();
  ASSERT_TRUE(finished.wait(10000));
  ASSERT_EQ(frames.count(), 5);
  const auto f4 = frames.at(4).at(0).value<sim::InputFrame>();
  EXPECT_NEAR(f4.time, 0.04, 1e-12);
  EXPECT_EQ(f4.hands[1].position, Eigen::Vector3d(4, 0, 0));

  // a tracker stream round trip
  const PoseStream stream = testing::pivotStream("Stylus", {1, 2, 3}, {4, 5, 6}, 10, 10.0, 0.01);
  const QString streamPath = dir.filePath(QStringLiteral("s.json"));
  ASSERT_TRUE(writePoseStream(streamPath, stream).ok());
  PoseStream back;
  ASSERT_TRUE(readPoseStream(streamPath, back).ok());
  ASSERT_EQ(back.samples.size(), stream.samples.size());
  EXPECT_EQ(std::get<RawPose>(back.samples[7]), std::get<RawPose>(stream.samples[7]));
  EXPECT_TRUE(openReplay(streamPath, fastConfig(), status));

  // neither, and a damaged stream naming the sample and field
  const QString junk = dir.filePath(QStringLiteral("junk.txt"));
  {
    QFile f(junk);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write("hello");
  }
  EXPECT_FALSE(openReplay(junk, fastConfig(), status));
  EXPECT_EQ(status.error, ReplayFileError::NotAReplay);
  PoseStream bad;
  const PoseStreamStatus s = decodePoseStream(
      R"({"format":"microsim-tracker-stream","version":1,"samples":[{"device":"A","time":0,"matrix":[1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1]},{"device":"A","time":1,"matrix":[1,2]}]})",
      bad);
  EXPECT_EQ(s.error, PoseStreamError::BadSample);
  EXPECT_EQ(s.sample, 1);
  EXPECT_EQ(s.field, QStringLiteral("matrix"));
}

}  // namespace
}  // namespace microsim::tracking
