// The game controller through the real SDL2 library: a virtual controller
// (tests/support/virtual_gamepad.h) is plugged in, found and read as a USB pad would be, and
// the InputFrames the source produces are checked value by value.
#include "tracking/gamepad_source.h"

#include "support/virtual_gamepad.h"

#include <QSignalSpy>

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include <numbers>

namespace microsim::tracking {
namespace {

GamepadSourceOptions steppedByTheTest() {
  GamepadSourceOptions o;
  o.pollIntervalMs = 0;
  o.scale.deadZone = 0.0;
  return o;
}

sim::InputFrame lastGamepadFrame(const QSignalSpy& spy) { return spy.last().at(0).value<sim::InputFrame>(); }

// a view looking along −x: right is +y, up is +z, the viewer sits at +x
ViewAxes gamepadSideView() {
  return {Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX()};
}

sim::InputFrame gamepadTools(const Eigen::Vector3d& left, const Eigen::Vector3d& right) {
  sim::InputFrame f;
  f.hands[0].tracked = true;
  f.hands[0].position = left;
  f.hands[1].tracked = true;
  f.hands[1].position = right;
  return f;
}

// each test plugs in its own virtual controller, and steps aside for a real one
class GamepadSourceWithPad : public ::testing::Test {
 protected:
  void SetUp() override {
    if (pad.controllersBefore() > 0) GTEST_SKIP() << "a real game controller is plugged in here";
    ASSERT_TRUE(pad.pluggedIn()) << pad.error();
  }
  testing::VirtualGamepad pad;
};

TEST_F(GamepadSourceWithPad, TheLeftStickMovesTheActiveToolInTheViewPlane) {
  GamepadSource source(steppedByTheTest());
  source.setTools(gamepadTools({-1, 0, 0}, {1, 0, 0}));
  source.setViewAxesProvider(gamepadSideView);
  QSignalSpy frames(&source, &TrackerSource::frameReady);
  source.start();
  ASSERT_TRUE(source.status().connected) << source.status().lastError.toStdString();
  EXPECT_EQ(source.deviceName(), QString::fromUtf8(testing::VirtualGamepad::kName));

  // a controller at rest sends nothing
  source.advance(0.1);
  EXPECT_EQ(frames.count(), 0);

  // full right and half up for 0.1 s: 2 mm/s along the view's right (+y), 1 mm/s along up (+z)
  pad.setAxis(SDL_CONTROLLER_AXIS_LEFTX, 32767);
  pad.setAxis(SDL_CONTROLLER_AXIS_LEFTY, -16384);
  source.advance(0.1);
  ASSERT_EQ(frames.count(), 1);
  const sim::InputFrame moved = lastGamepadFrame(frames);
  const Eigen::Vector3d expected(1.0, 0.2, 0.2 * 16384.0 / 32767.0);
  EXPECT_LT((moved.hand(sim::Hand::Right).position - expected).norm(), 1e-12);
  EXPECT_EQ(moved.hand(sim::Hand::Left).position, Eigen::Vector3d(-1, 0, 0));
  EXPECT_EQ(moved.hand(sim::Hand::Right).orientation.coeffs(), Eigen::Quaterniond::Identity().coeffs());
  sim::InputRejection why{};
  EXPECT_TRUE(sim::validateFrame(moved, why));
  source.stop();
}

TEST_F(GamepadSourceWithPad, AToolPushedOnStopsAtTheWorkingVolume) {
  GamepadSource source(steppedByTheTest());
  source.setTools(gamepadTools({-1, 0, 0}, {1, 0, 0}));
  source.setViewAxesProvider(gamepadSideView);
  // the keyboard's box around the scene: the right tip may go 0.5 mm further along +y
  const Eigen::AlignedBox3d box(Eigen::Vector3d(-2, -0.5, -0.5), Eigen::Vector3d(2, 0.5, 0.5));
  source.setWorkingVolumeProvider([box] { return std::optional<Eigen::AlignedBox3d>(box); });
  QSignalSpy frames(&source, &TrackerSource::frameReady);
  source.start();
  ASSERT_TRUE(source.status().connected) << source.status().lastError.toStdString();

  // full right for 2 s (4 mm at 2 mm/s): the tip stops at the box's face, the other axes kept
  pad.setAxis(SDL_CONTROLLER_AXIS_LEFTX, 32767);
  for (int k = 0; k < 20; ++k) source.advance(0.1);
  ASSERT_GT(frames.count(), 0);
  const sim::InputFrame pushed = lastGamepadFrame(frames);
  EXPECT_EQ(pushed.hand(sim::Hand::Right).position, Eigen::Vector3d(1, 0.5, 0));
  EXPECT_EQ(pushed.hand(sim::Hand::Left).position, Eigen::Vector3d(-1, 0, 0));
  source.stop();
}

TEST_F(GamepadSourceWithPad, TriggersCloseEachHandsJawsGraduallyAndShouldersChooseTheHand) {
  GamepadSource source(steppedByTheTest());
  source.setTools(gamepadTools({-1, 0, 0}, {1, 0, 0}));
  source.setViewAxesProvider(gamepadSideView);
  QSignalSpy frames(&source, &TrackerSource::frameReady);
  QSignalSpy hands(&source, &RateToolSource::activeHandChanged);
  source.start();
  ASSERT_TRUE(source.status().connected);

  pad.setTrigger(SDL_CONTROLLER_AXIS_TRIGGERLEFT, 0.5);
  pad.setTrigger(SDL_CONTROLLER_AXIS_TRIGGERRIGHT, 1.0);
  source.advance(0.01);
  ASSERT_GE(frames.count(), 1);
  EXPECT_NEAR(lastGamepadFrame(frames).hand(sim::Hand::Left).closure, 0.5, 1e-4);  // SDL's integer steps
  EXPECT_EQ(lastGamepadFrame(frames).hand(sim::Hand::Right).closure, 1.0);
  // triggers held where they are: nothing new
  const qsizetype before = frames.count();
  source.advance(0.01);
  EXPECT_EQ(frames.count(), before);

  // the left shoulder makes the left hand active; the right stick pushed up takes it away
  // from the viewer (−x here) and pushed right turns it about the view's up (+z), clockwise
  pad.setButton(SDL_CONTROLLER_BUTTON_LEFTSHOULDER, true);
  pad.setAxis(SDL_CONTROLLER_AXIS_RIGHTY, -32768);
  pad.setAxis(SDL_CONTROLLER_AXIS_RIGHTX, 32767);
  source.advance(0.5);
  ASSERT_EQ(hands.count(), 1);
  EXPECT_EQ(source.activeHand(), sim::Hand::Left);
  const sim::HandInput left = lastGamepadFrame(frames).hand(sim::Hand::Left);
  EXPECT_LT((left.position - Eigen::Vector3d(-1.0 - 1.0, 0, 0)).norm(), 1e-12);  // 2 mm/s · 0.5 s
  const Eigen::AngleAxisd turn(left.orientation);
  EXPECT_NEAR(turn.angle(), 30.0 * std::numbers::pi / 180.0, 1e-12);  // 60°/s · 0.5 s
  EXPECT_LT((turn.axis() + Eigen::Vector3d::UnitZ()).norm(), 1e-9);
  EXPECT_EQ(lastGamepadFrame(frames).hand(sim::Hand::Right).position, Eigen::Vector3d(1, 0, 0));
  source.stop();
}

TEST_F(GamepadSourceWithPad, YSwapsTheActiveHandsForcepsForTheScissorsAndTheTriggerClosesThem) {
  GamepadSource source(steppedByTheTest());
  source.setTools(gamepadTools({-1, 0, 0}, {1, 0, 0}));
  QSignalSpy frames(&source, &TrackerSource::frameReady);
  source.start();
  ASSERT_TRUE(source.status().connected);

  pad.setButton(SDL_CONTROLLER_BUTTON_Y, true);
  source.advance(0.01);
  source.advance(0.01);  // held: one swap
  ASSERT_GE(frames.count(), 1);
  EXPECT_EQ(lastGamepadFrame(frames).hand(sim::Hand::Right).instrument, sim::Instrument::Scissors);
  EXPECT_EQ(lastGamepadFrame(frames).hand(sim::Hand::Left).instrument, sim::Instrument::Forceps);
  pad.setTrigger(SDL_CONTROLLER_AXIS_TRIGGERRIGHT, 1.0);
  source.advance(0.01);
  EXPECT_EQ(lastGamepadFrame(frames).hand(sim::Hand::Right).closure, 1.0);
  EXPECT_EQ(lastGamepadFrame(frames).hand(sim::Hand::Right).instrument, sim::Instrument::Scissors);

  // released and pressed again: the forceps, taken up open
  pad.setButton(SDL_CONTROLLER_BUTTON_Y, false);
  source.advance(0.01);
  pad.setButton(SDL_CONTROLLER_BUTTON_Y, true);
  source.advance(0.01);
  EXPECT_EQ(lastGamepadFrame(frames).hand(sim::Hand::Right).instrument, sim::Instrument::Forceps);
  EXPECT_EQ(lastGamepadFrame(frames).hand(sim::Hand::Right).closure, 0.0);

  // a scene without scissors: Y swaps nothing
  source.setScissorsInScene([] { return false; });
  pad.setButton(SDL_CONTROLLER_BUTTON_Y, false);
  source.advance(0.01);
  const qsizetype before = frames.count();
  pad.setButton(SDL_CONTROLLER_BUTTON_Y, true);
  source.advance(0.01);
  EXPECT_EQ(frames.count(), before);
  source.stop();
}

TEST_F(GamepadSourceWithPad, AMotionStartsFromTheToolsWhereTheSceneShowsThem) {
  GamepadSource source(steppedByTheTest());
  sim::InputFrame shown = gamepadTools({-2, 0, 0}, {2, 0, 0});
  source.setToolAnchor([&shown] { return std::optional<sim::InputFrame>(shown); });
  QSignalSpy frames(&source, &TrackerSource::frameReady);
  source.start();

  pad.setAxis(SDL_CONTROLLER_AXIS_LEFTX, 32767);
  source.advance(0.1);
  source.advance(0.1);  // still moving: integrates its own frame, the anchor is not read again
  shown = gamepadTools({-5, 0, 0}, {5, 0, 0});
  source.advance(0.1);
  EXPECT_LT((lastGamepadFrame(frames).hand(sim::Hand::Right).position - Eigen::Vector3d(2.6, 0, 0)).norm(), 1e-12);

  // let go, then move again: the tools are taken where they are shown now (the keyboard or
  // another device may have moved them)
  pad.setAxis(SDL_CONTROLLER_AXIS_LEFTX, 0);
  source.advance(0.1);
  pad.setAxis(SDL_CONTROLLER_AXIS_LEFTX, -32768);
  source.advance(0.1);
  EXPECT_LT((lastGamepadFrame(frames).hand(sim::Hand::Right).position - Eigen::Vector3d(4.8, 0, 0)).norm(), 1e-12);
  EXPECT_EQ(lastGamepadFrame(frames).hand(sim::Hand::Left).position, Eigen::Vector3d(-5, 0, 0));
  source.stop();
}

TEST_F(GamepadSourceWithPad, PollsOnItsOwnWhileTheEventLoopRuns) {
  GamepadSource source;  // polls every 10 ms
  source.setTools(gamepadTools({-1, 0, 0}, {1, 0, 0}));
  QSignalSpy frames(&source, &TrackerSource::frameReady);
  source.start();
  pad.setAxis(SDL_CONTROLLER_AXIS_LEFTX, 32767);
  ASSERT_TRUE(frames.wait(10000));
  EXPECT_GT(lastGamepadFrame(frames).hand(sim::Hand::Right).position.x(), 1.0);
  source.stop();
  const qsizetype stopped = frames.count();
  EXPECT_FALSE(frames.wait(100));  // nothing after stop()
  EXPECT_EQ(frames.count(), stopped);
}

TEST_F(GamepadSourceWithPad, UnpluggingMarksTheHandsUntrackedAndSaysWhich) {
  GamepadSource source(steppedByTheTest());
  source.setTools(gamepadTools({-1, 0, 0}, {1, 0, 0}));
  QSignalSpy frames(&source, &TrackerSource::frameReady);
  QSignalSpy down(&source, &TrackerSource::linkDown);
  source.start();
  ASSERT_TRUE(source.status().connected);
  pad.unplug();
  source.advance(0.01);
  ASSERT_EQ(down.count(), 1);
  EXPECT_FALSE(source.status().connected);
  EXPECT_TRUE(source.status().lastError.contains(QString::fromUtf8(testing::VirtualGamepad::kName)));
  ASSERT_EQ(frames.count(), 1);
  EXPECT_FALSE(lastGamepadFrame(frames).hand(sim::Hand::Left).tracked);
  EXPECT_FALSE(lastGamepadFrame(frames).hand(sim::Hand::Right).tracked);
  source.advance(0.01);  // no controller, no crash, nothing more
  EXPECT_EQ(frames.count(), 1);
}

TEST(GamepadSource, WithoutAControllerItSaysSoAndProducesNothing) {
  SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
  ASSERT_EQ(SDL_InitSubSystem(SDL_INIT_GAMECONTROLLER), 0);
  const int present = SDL_NumJoysticks();
  SDL_QuitSubSystem(SDL_INIT_GAMECONTROLLER);
  if (present > 0) GTEST_SKIP() << "a game controller is plugged in here";
  GamepadSource source(steppedByTheTest());
  QSignalSpy frames(&source, &TrackerSource::frameReady);
  QSignalSpy down(&source, &TrackerSource::linkDown);
  source.start();
  EXPECT_EQ(down.count(), 1);
  EXPECT_FALSE(source.status().connected);
  EXPECT_TRUE(source.status().lastError.contains(QStringLiteral("No game controller")));
  source.advance(0.1);
  EXPECT_EQ(frames.count(), 0);
}

}  // namespace
}  // namespace microsim::tracking
