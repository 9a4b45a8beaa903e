// The OpenIGTLink decoder against the library's own encoder, and against broken streams.
#include "tracking/igtl_decoder.h"

#include "app/tracking/igtl_test_server.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace microsim::tracking {
namespace {

using testing::floatPose;
using testing::igtlTime;
using testing::packed;
using testing::rawMessage;

std::vector<std::uint8_t> operator+(std::vector<std::uint8_t> a, const std::vector<std::uint8_t>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

std::vector<std::uint8_t> floats(std::initializer_list<float> values) {
  std::vector<std::uint8_t> out;
  for (float f : values) {
    std::uint32_t u;
    std::memcpy(&u, &f, 4);
    for (int s = 24; s >= 0; s -= 8) out.push_back(static_cast<std::uint8_t>(u >> s));
  }
  return out;
}

TEST(IgtlDecoder, ReadsTransformPositionTdataAndSensorFromTheLibrary) {
  const Eigen::Matrix4d a = floatPose(0.3, {1, 2, 3}, {10.5, -4.25, 7});
  const Eigen::Matrix4d b = floatPose(-1.1, {0, 1, 0}, {1, 2, 3});
  igtl::TrackingDataMessage::Pointer tdata = igtl::TrackingDataMessage::New();
  tdata->SetDeviceName("Tracker");
  for (const char* name : {"Stylus", "Ref"}) {
    igtl::TrackingDataElement::Pointer e = igtl::TrackingDataElement::New();
    e->SetName(name);
    e->SetType(igtl::TrackingDataElement::TYPE_6D);
    igtl::Matrix4x4 f;
    const Eigen::Matrix4d& m = std::string(name) == "Stylus" ? a : b;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) f[r][c] = static_cast<float>(m(r, c));
    e->SetMatrix(f);
    tdata->AddTrackingDataElement(e);
  }
  testing::setTime(tdata, 12.5);
  const Eigen::Quaternionf q(Eigen::AngleAxisf(0.5f, Eigen::Vector3f::UnitZ()));

  const std::vector<std::uint8_t> stream = packed(testing::transformMessage("Left", a, 100.25)) +
                                           packed(testing::positionMessage("Right", {1, 2, 3}, q, 100.5)) +
                                           packed(tdata) + packed(testing::sensorMessage("Grip", 42.5, 101.0));
  IgtlDecoder decoder;
  IgtlDecodeOutput out;
  // byte by byte: framing may not depend on how the socket splits the stream
  for (std::uint8_t byte : stream) decoder.feed({&byte, 1}, 0.0, out);

  EXPECT_TRUE(out.rejections.empty());
  ASSERT_EQ(out.poses.size(), 4u);
  EXPECT_EQ(out.poses[0], (RawPose{"Left", igtlTime(100.25), a, true}));
  EXPECT_EQ(out.poses[1].device, "Right");
  EXPECT_EQ(out.poses[1].time, 100.5);
  EXPECT_EQ(Eigen::Vector3d(out.poses[1].matrix.topRightCorner<3, 1>()), Eigen::Vector3d(1, 2, 3));
  EXPECT_LT((out.poses[1].matrix.topLeftCorner<3, 3>() - q.cast<double>().toRotationMatrix()).norm(), 1e-6);
  EXPECT_EQ(out.poses[2], (RawPose{"Stylus", 12.5, a, true}));
  EXPECT_EQ(out.poses[3], (RawPose{"Ref", 12.5, b, true}));
  ASSERT_EQ(out.channels.size(), 1u);
  EXPECT_EQ(out.channels[0], (ChannelValue{"Grip", 101.0, 42.5}));
  EXPECT_EQ(decoder.buffered(), 0u);
  // the stream order survives across the lists
  ASSERT_EQ(out.order.size(), 5u);
  EXPECT_EQ(out.order[3].kind, IgtlDecodeOutput::Kind::Pose);
  EXPECT_EQ(out.order[4].kind, IgtlDecodeOutput::Kind::Channel);
}

TEST(IgtlDecoder, PositionOnlyAndNoTimestamp) {
  const std::vector<std::uint8_t> stream = tracking::encodeIgtlHeader("POSITION", "Tip", 0, floats({1.5f, 2, 3})) +
                                           floats({1.5f, 2, 3});
  IgtlDecoder decoder;
  IgtlDecodeOutput out;
  decoder.feed(stream, 7.0, out);
  ASSERT_EQ(out.poses.size(), 1u);
  EXPECT_FALSE(out.poses[0].hasRotation);
  EXPECT_EQ(out.poses[0].time, 7.0);  // the receive time stands in
  EXPECT_EQ(Eigen::Vector3d(out.poses[0].matrix.topRightCorner<3, 1>()), Eigen::Vector3d(1.5, 2, 3));
  EXPECT_EQ(Eigen::Matrix3d(out.poses[0].matrix.topLeftCorner<3, 3>()), Eigen::Matrix3d(Eigen::Matrix3d::Identity()));
}

TEST(IgtlDecoder, RefusesEachKindOfBrokenMessageAndKeepsReading) {
  const Eigen::Matrix4d a = floatPose(0.2, {0, 0, 1}, {1, 2, 3});
  const std::vector<std::uint8_t> good = packed(testing::transformMessage("Left", a, 5.0));
  const std::vector<std::uint8_t> body48(good.begin() + kIgtlHeaderSize, good.end());
  const std::vector<std::uint8_t> body40(body48.begin(), body48.begin() + 40);
  std::vector<std::uint8_t> garbage(100, 0xff);
  const std::vector<std::uint8_t> stream =
      rawMessage("TRANSFORM", "Left", 5.0, body48, /*breakCrc=*/true) +  // bad CRC
      rawMessage("TRANSFORM", "Left", 5.0, body40) +                     // wrong body size
      rawMessage("POSITION", "Left", 5.0, body40) +                      // wrong body size
      rawMessage("SENSOR", "Grip", 5.0, {1, 0, 0, 0, 0, 0, 0, 0, 0, 0}) + // wrong body size (no value)
      rawMessage("IMAGE", "US", 5.0, {1, 2, 3, 4}) +                     // unknown type
      garbage +                                                          // not a header: resync
      good + good;
  IgtlDecoder decoder;
  IgtlDecodeOutput out;
  decoder.feed(stream, 0.0, out);
  EXPECT_EQ(out.rejections, (std::vector<Rejection>{Rejection::BadCrc, Rejection::WrongBodySize, Rejection::WrongBodySize,
                                                    Rejection::WrongBodySize, Rejection::UnknownType, Rejection::BadHeader}));
  ASSERT_EQ(out.poses.size(), 2u);
  EXPECT_EQ(out.poses[1].matrix, a);

  // a message cut by the end of the stream
  out.clear();
  decoder.feed(std::span(good).first(kIgtlHeaderSize + 20), 0.0, out);
  EXPECT_TRUE(out.poses.empty());
  decoder.endOfStream(out);
  EXPECT_EQ(out.rejections, std::vector<Rejection>{Rejection::Truncated});
  EXPECT_EQ(decoder.buffered(), 0u);

  // an absurd body size is garbage, not a 2^40-byte wait
  out.clear();
  std::vector<std::uint8_t> huge = good;
  huge[42] = 0x01;  // body size's high bytes
  decoder.feed(huge + good, 0.0, out);
  EXPECT_EQ(out.rejections, std::vector<Rejection>{Rejection::BadHeader});
  EXPECT_EQ(out.poses.size(), 1u);
}

TEST(IgtlDecoder, VersionTwoHeadersReadAndNonFiniteValuesPassThroughToTheFilter) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<std::uint8_t> body = floats({1, 0, 0, 0, 1, 0, 0, 0, 1, nan, 0, 0});
  const std::vector<std::uint8_t> stream = tracking::encodeIgtlHeader("TRANSFORM", "L", 0, body, 2) + body;
  IgtlDecoder decoder;
  IgtlDecodeOutput out;
  decoder.feed(stream, 1.0, out);
  ASSERT_EQ(out.poses.size(), 1u);
  EXPECT_TRUE(std::isnan(out.poses[0].matrix(0, 3)));
}

}  // namespace
}  // namespace microsim::tracking
