// The numeric gate: each bad pose refused for its own reason, the reference never dragged.
#include "tracking/pose_filter.h"

#include "tracking/frame_assembler.h"

#include <gtest/gtest.h>

#include <limits>

namespace microsim::tracking {
namespace {

RawPose at(const std::string& device, double time, double x) {
  RawPose p;
  p.device = device;
  p.time = time;
  p.matrix(0, 3) = x;
  return p;
}

TEST(PoseFilter, RefusesNonFiniteSkewedBackwardsAndTooFastPoses) {
  PoseFilter filter(PoseLimits{.maxSpeed = 100.0, .jumpAllowance = 0.5, .orthonormalTolerance = 1e-3});
  EXPECT_FALSE(filter.check(at("L", 1.0, 0.0)));
  EXPECT_FALSE(filter.check(at("L", 1.1, 10.0)));  // 100 mm/s exactly

  RawPose nan = at("L", 1.2, 10.0);
  nan.matrix(1, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(filter.check(nan), Rejection::NonFinite);
  RawPose inf = at("L", std::numeric_limits<double>::infinity(), 10.0);
  EXPECT_EQ(filter.check(inf), Rejection::NonFinite);

  RawPose scaled = at("L", 1.2, 10.0);
  scaled.matrix.topLeftCorner<3, 3>() *= 1.01;
  EXPECT_EQ(filter.check(scaled), Rejection::NotOrthonormal);
  RawPose mirrored = at("L", 1.2, 10.0);
  mirrored.matrix(2, 2) = -1.0;  // orthogonal but a reflection
  EXPECT_EQ(filter.check(mirrored), Rejection::NotOrthonormal);

  EXPECT_EQ(filter.check(at("L", 1.05, 10.0)), Rejection::TimeBackwards);
  EXPECT_EQ(filter.check(at("L", 1.2, 30.0)), Rejection::TooFast);  // 200 mm/s
  // the reference stayed at (1.1 s, 10 mm): a slower move from there passes
  EXPECT_FALSE(filter.check(at("L", 1.2, 19.0)));
  // another device has its own reference
  EXPECT_FALSE(filter.check(at("R", 0.5, 500.0)));
  // a tool moved while unseen is accepted once the time allows the distance
  EXPECT_EQ(filter.check(at("L", 1.3, 100.0)), Rejection::TooFast);
  EXPECT_FALSE(filter.check(at("L", 2.2, 100.0)));

  // after a reset (new connection) the clock may restart
  filter.reset();
  EXPECT_FALSE(filter.check(at("L", 0.0, 100.0)));
}

TEST(PoseFilter, ChannelsMustBeFiniteAndInOrder) {
  PoseFilter filter;
  EXPECT_FALSE(filter.check(ChannelValue{"G", 1.0, 0.5}));
  EXPECT_EQ(filter.check(ChannelValue{"G", 0.5, 0.5}), Rejection::TimeBackwards);
  EXPECT_EQ(filter.check(ChannelValue{"G", 2.0, std::numeric_limits<double>::quiet_NaN()}), Rejection::NonFinite);
}

TEST(FrameAssembler, MapsDevicesToHandsAndClosureChannels) {
  DeviceMapping mapping;
  mapping.hands[0] = HandMapping{"LeftTool", sim::Instrument::Forceps, "LeftGrip", 10.0, 30.0};
  mapping.hands[1] = HandMapping{"RightTool", sim::Instrument::NeedleHolder, "", 0.0, 1.0};
  FrameAssembler assembler(mapping);

  RawPose left = at("LeftTool", 1.0, 5.0);
  left.matrix.topLeftCorner<3, 3>() = Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const std::optional<sim::InputFrame> f1 = assembler.applyPose(left, 3.0);
  ASSERT_TRUE(f1);
  EXPECT_EQ(f1->time, 3.0);
  EXPECT_TRUE(f1->hand(sim::Hand::Left).tracked);
  EXPECT_FALSE(f1->hand(sim::Hand::Right).tracked);
  EXPECT_EQ(f1->hand(sim::Hand::Right).instrument, sim::Instrument::NeedleHolder);
  EXPECT_EQ(f1->hand(sim::Hand::Left).position, Eigen::Vector3d(5, 0, 0));
  EXPECT_NEAR(f1->hand(sim::Hand::Left).orientation.angularDistance(
                  Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitX()))),
              0.0, 1e-12);

  EXPECT_FALSE(assembler.applyPose(at("Other", 1.0, 0.0), 3.1));
  EXPECT_FALSE(assembler.applyChannel(ChannelValue{"Other", 1.0, 0.0}, 3.1));
  EXPECT_EQ(assembler.applyChannel(ChannelValue{"LeftGrip", 1.1, 20.0}, 3.2)->hand(sim::Hand::Left).closure, 0.5);
  EXPECT_EQ(assembler.applyChannel(ChannelValue{"LeftGrip", 1.2, 99.0}, 3.3)->hand(sim::Hand::Left).closure, 1.0);

  // a position-only device keeps the last orientation
  RawPose positionOnly = at("LeftTool", 1.3, 6.0);
  positionOnly.hasRotation = false;
  const sim::InputFrame f2 = *assembler.applyPose(positionOnly, 3.4);
  EXPECT_EQ(f2.hand(sim::Hand::Left).orientation.coeffs(), f1->hand(sim::Hand::Left).orientation.coeffs());

  const sim::InputFrame lost = assembler.lose(4.0);
  EXPECT_FALSE(lost.hand(sim::Hand::Left).tracked);
  EXPECT_EQ(lost.hand(sim::Hand::Left).position, Eigen::Vector3d(6, 0, 0));
}

}  // namespace
}  // namespace microsim::tracking
