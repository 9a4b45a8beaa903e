#include "tracking/gamepad_mapping.h"

#include <gtest/gtest.h>

namespace microsim::tracking {
namespace {

TEST(GamepadMapping, SticksMoveInTheViewPlaneAndInDepthAndTurnAboutUp) {
  GamepadState s;
  s.leftX = 1.0;    // right
  s.leftY = -1.0;   // pushed up (SDL's y grows downward)
  s.rightY = -1.0;  // pushed up: away from the viewer
  s.rightX = 1.0;   // right: turn clockwise seen from above, as the → key does
  const RateCommand c = gamepadCommand(s, {0.0});
  EXPECT_EQ(c.translation, Eigen::Vector3d(1.0, 1.0, -1.0));
  EXPECT_EQ(c.rotation, Eigen::Vector3d(0.0, -1.0, 0.0));
}

TEST(GamepadMapping, TheDpadTiltsAndRolls) {
  GamepadState s;
  s.dpadUp = true;    // tilt as ↑ does: about right, negative
  s.dpadLeft = true;  // roll anticlockwise as the viewer sees it
  const RateCommand c = gamepadCommand(s);
  EXPECT_EQ(c.rotation, Eigen::Vector3d(-1.0, 0.0, 1.0));
  EXPECT_TRUE(c.translation.isZero(0.0));
}

TEST(GamepadMapping, ARestingStickInsideTheDeadZoneDoesNothing) {
  GamepadState s;
  s.leftX = 0.1;
  s.rightY = -0.12;
  EXPECT_TRUE(gamepadCommand(s, {0.15}).isZero());
  s.leftX = 0.575;
  EXPECT_NEAR(gamepadCommand(s, {0.15}).translation.x(), 0.5, 1e-12);
}

TEST(GamepadMapping, TriggersCloseTheirHandsJawsGradually) {
  GamepadState s;
  s.leftTrigger = 0.5;
  s.rightTrigger = 1.5;  // clamped
  const auto closures = gamepadClosures(s);
  EXPECT_EQ(closures[0], 0.5);
  EXPECT_EQ(closures[1], 1.0);
}

TEST(GamepadMapping, SdlAxisUnitsBecomeMinusOneToOne) {
  EXPECT_EQ(gamepadAxis(32767), 1.0);
  EXPECT_EQ(gamepadAxis(-32768), -1.0);
  EXPECT_EQ(gamepadAxis(0), 0.0);
}

}  // namespace
}  // namespace microsim::tracking
