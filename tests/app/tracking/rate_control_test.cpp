#include "tracking/rate_control.h"

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include <numbers>

namespace microsim::tracking {
namespace {

// a view looking along −x: right is +y, up is +z, the viewer sits at +x
ViewAxes rateSideView() { return {Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX()}; }

sim::HandInput rateHandAt(const Eigen::Vector3d& p) {
  sim::HandInput h;
  h.tracked = true;
  h.position = p;
  h.closure = 0.25;
  return h;
}

TEST(RateControl, ADeflectionMovesTheTipAlongTheViewAxesAtTheLimitRate) {
  RateCommand c;
  c.translation = {0.5, -1.0, 0.25};  // half right, full down, a quarter toward the viewer
  const RateLimits limits{2.0, 60.0};
  const sim::HandInput out = applyRate(rateHandAt({1, 2, 3}), c, rateSideView(), limits, 0.1);
  // 2 mm/s · 0.1 s = 0.2 mm per unit of deflection
  EXPECT_LT((out.position - Eigen::Vector3d(1 + 0.2 * 0.25, 2 + 0.2 * 0.5, 3 - 0.2)).norm(), 1e-12);
  EXPECT_EQ(out.orientation.coeffs(), Eigen::Quaterniond::Identity().coeffs());
  EXPECT_EQ(out.closure, 0.25);
  EXPECT_TRUE(out.tracked);
}

TEST(RateControl, ATwistTurnsTheToolAboutTheViewAxisAtItsTipAndClampsToFullDeflection) {
  RateCommand c;
  c.rotation = {0.0, 3.0, 0.0};  // past full deflection about up: clamped to 1
  const sim::HandInput out = applyRate(rateHandAt({1, 2, 3}), c, rateSideView(), {2.0, 60.0}, 0.5);
  EXPECT_EQ(out.position, Eigen::Vector3d(1, 2, 3));  // about the tip: it stays
  const Eigen::AngleAxisd turned(out.orientation);
  EXPECT_NEAR(turned.angle(), 30.0 * std::numbers::pi / 180.0, 1e-12);  // 60°/s · 0.5 s
  EXPECT_LT((turned.axis() - Eigen::Vector3d::UnitZ()).norm(), 1e-12);    // the view's up
}

TEST(RateControl, NoDeflectionOrNoTimeLeavesTheHandAsItWas) {
  const sim::HandInput in = rateHandAt({1, 2, 3});
  EXPECT_EQ(applyRate(in, RateCommand{}, rateSideView(), {}, 0.1), in);
  RateCommand c;
  c.translation = {1, 1, 1};
  c.rotation = {1, 0, 0};
  EXPECT_EQ(applyRate(in, c, rateSideView(), {}, 0.0).position, in.position);
}

TEST(RateControl, TheDeadZoneSwallowsRestNoiseAndTheResponseReachesOneAtFullDeflection) {
  EXPECT_EQ(pastDeadZone(0.1, 0.15), 0.0);
  EXPECT_EQ(pastDeadZone(-0.15, 0.15), 0.0);
  EXPECT_NEAR(pastDeadZone(0.575, 0.15), 0.5, 1e-12);
  EXPECT_NEAR(pastDeadZone(-0.575, 0.15), -0.5, 1e-12);
  EXPECT_EQ(pastDeadZone(1.0, 0.15), 1.0);
  EXPECT_EQ(pastDeadZone(-2.0, 0.15), -1.0);
}

TEST(RateControl, TheToolsShownBecomeTheFrameThatPutsThemThere) {
  sim::RenderSnapshot snapshot;
  EXPECT_FALSE(toolsShown(snapshot).has_value());  // no forceps in the scene

  sim::ToolSnapshot& right = snapshot.forceps[1];
  right.present = true;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 1, 0).normalized()).toRotationMatrix();
  pose.translation() = Eigen::Vector3d(0.5, -0.25, 1.5);
  right.pose = pose.matrix().cast<float>();
  right.closure = 0.75;
  const std::optional<sim::InputFrame> frame = toolsShown(snapshot);
  ASSERT_TRUE(frame.has_value());
  EXPECT_FALSE(frame->hand(sim::Hand::Left).tracked);
  const sim::HandInput& hand = frame->hand(sim::Hand::Right);
  EXPECT_TRUE(hand.tracked);
  EXPECT_EQ(hand.closure, 0.75);
  EXPECT_LT((hand.position - pose.translation()).norm(), 1e-6);  // single precision
  EXPECT_LT(hand.orientation.angularDistance(Eigen::Quaterniond(pose.linear())), 1e-6);
  sim::InputRejection why{};
  EXPECT_TRUE(sim::validateFrame(*frame, why));
  EXPECT_EQ(hand.instrument, sim::Instrument::Forceps);

  // a hand that holds the scissors: the instrument and the blades' closure, not the put-down jaws'
  snapshot.instruments[1] = sim::Instrument::Scissors;
  snapshot.scissors[1].present = true;
  snapshot.scissors[1].pose = right.pose;
  snapshot.scissors[1].closure = 0.4;
  right.closure = 0.0;
  const std::optional<sim::InputFrame> cutting = toolsShown(snapshot);
  ASSERT_TRUE(cutting.has_value());
  EXPECT_EQ(cutting->hand(sim::Hand::Right).instrument, sim::Instrument::Scissors);
  EXPECT_EQ(cutting->hand(sim::Hand::Right).closure, 0.4);
}

}  // namespace
}  // namespace microsim::tracking
