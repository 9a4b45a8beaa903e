#include "tracking/spacenav_mapping.h"

#include <gtest/gtest.h>

namespace microsim::tracking {
namespace {

TEST(SpacenavMapping, TheDaemonsLeftHandedAxesBecomeTheViewsRightHandedOnes) {
  const SpacenavScale scale{350.0, 0.0, 0.05};
  // pushing right, lifting, pressing into the screen
  const RateCommand push = spacenavCommand({175, 350, 70, 0, 0, 0, 16}, scale);
  EXPECT_NEAR(push.translation.x(), 0.5, 1e-12);
  EXPECT_NEAR(push.translation.y(), 1.0, 1e-12);
  EXPECT_NEAR(push.translation.z(), -0.2, 1e-12);  // into the screen = away from the viewer
  EXPECT_TRUE(push.rotation.isZero(0.0));
  // the reflection of z flips the sense of the turns about x and y, not about z
  const RateCommand twist = spacenavCommand({0, 0, 0, 35, -70, 175, 16}, scale);
  EXPECT_NEAR(twist.rotation.x(), -0.1, 1e-12);
  EXPECT_NEAR(twist.rotation.y(), 0.2, 1e-12);
  EXPECT_NEAR(twist.rotation.z(), 0.5, 1e-12);
  EXPECT_TRUE(twist.translation.isZero(0.0));
}

TEST(SpacenavMapping, ACapRestingNearZeroIsNoMotionAndFullDeflectionIsOne) {
  const SpacenavScale scale;  // 350 counts, 4 % dead zone
  EXPECT_TRUE(spacenavCommand({10, -12, 13, 5, -9, 3, 16}, scale).isZero());
  const RateCommand full = spacenavCommand({700, 0, 0, 0, 0, 0, 16}, scale);  // beyond full scale
  EXPECT_EQ(full.translation.x(), 1.0);
}

TEST(SpacenavMapping, AnEventMovesForItsPeriodButNoLongerThanTheLongestStep) {
  EXPECT_NEAR(spacenavStep({0, 0, 0, 0, 0, 0, 16}), 0.016, 1e-15);
  EXPECT_EQ(spacenavStep({0, 0, 0, 0, 0, 0, 4000}), SpacenavScale{}.maxStepS);  // after a rest
}

TEST(SpacenavMapping, ButtonZeroHoldsTheJawsOneSwitchesTheHandTwoTheInstrument) {
  EXPECT_EQ(spacenavButtonAction(0), SpacenavButtonAction::HoldJaws);
  EXPECT_EQ(spacenavButtonAction(1), SpacenavButtonAction::SwitchHand);
  EXPECT_EQ(spacenavButtonAction(2), SpacenavButtonAction::SwitchInstrument);
  EXPECT_EQ(spacenavButtonAction(3), SpacenavButtonAction::None);
}

}  // namespace
}  // namespace microsim::tracking
