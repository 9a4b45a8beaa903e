#include "tracking/manual_source.h"

#include <QSignalSpy>

#include <gtest/gtest.h>

#include <numbers>

namespace microsim::tracking {
namespace {

sim::InputFrame lastFrame(const QSignalSpy& spy) {
  return spy.last().at(0).value<sim::InputFrame>();
}

TEST(ManualSource, KeysMoveTheActiveTipByTheDocumentedStepInTheView) {
  ManualSource source;
  source.setViewBasis(Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ());
  QSignalSpy frames(&source, &TrackerSource::frameReady);
  source.start();
  ASSERT_EQ(frames.count(), 1);
  const sim::InputFrame start = lastFrame(frames);
  EXPECT_TRUE(start.hand(sim::Hand::Left).tracked);
  EXPECT_TRUE(start.hand(sim::Hand::Right).tracked);
  ASSERT_EQ(source.activeHand(), sim::Hand::Right);

  const Eigen::Vector3d p0 = start.hand(sim::Hand::Right).position;
  EXPECT_TRUE(source.handleKey(Qt::Key_D, Qt::NoModifier, true, false));
  EXPECT_TRUE(source.handleKey(Qt::Key_D, Qt::NoModifier, false, false));  // release: no move
  EXPECT_TRUE(source.handleKey(Qt::Key_W, Qt::NoModifier, true, true));    // a key repeat moves
  EXPECT_TRUE(source.handleKey(Qt::Key_Q, Qt::ShiftModifier, true, false));
  const sim::InputFrame moved = lastFrame(frames);
  const Eigen::Vector3d expected =
      p0 + Eigen::Vector3d(ManualSource::kStepMm, ManualSource::kStepMm, -ManualSource::kFineStepMm);
  EXPECT_LT((moved.hand(sim::Hand::Right).position - expected).norm(), 1e-12);
  EXPECT_EQ(moved.hand(sim::Hand::Left).position, start.hand(sim::Hand::Left).position);
  EXPECT_GE(moved.time, start.time);

  // Tab switches the hand; the left one moves now
  EXPECT_TRUE(source.handleKey(Qt::Key_Tab, Qt::NoModifier, true, false));
  EXPECT_EQ(source.activeHand(), sim::Hand::Left);
  EXPECT_TRUE(source.handleKey(Qt::Key_A, Qt::NoModifier, true, false));
  EXPECT_LT((lastFrame(frames).hand(sim::Hand::Left).position - start.hand(sim::Hand::Left).position -
             Eigen::Vector3d(-ManualSource::kStepMm, 0, 0)).norm(), 1e-12);

  // Space closes while held
  EXPECT_TRUE(source.handleKey(Qt::Key_Space, Qt::NoModifier, true, false));
  EXPECT_EQ(lastFrame(frames).hand(sim::Hand::Left).closure, 1.0);
  EXPECT_TRUE(source.handleKey(Qt::Key_Space, Qt::NoModifier, false, false));
  EXPECT_EQ(lastFrame(frames).hand(sim::Hand::Left).closure, 0.0);

  // an arrow turns the tool by the step angle about the view's up axis
  const Eigen::Quaterniond q0 = lastFrame(frames).hand(sim::Hand::Left).orientation;
  EXPECT_TRUE(source.handleKey(Qt::Key_Left, Qt::NoModifier, true, false));
  const Eigen::Quaterniond q1 = lastFrame(frames).hand(sim::Hand::Left).orientation;
  EXPECT_NEAR(q0.angularDistance(q1) * 180.0 / 3.14159265358979, ManualSource::kStepDeg, 1e-9);
  sim::InputRejection why{};
  EXPECT_TRUE(sim::validateFrame(lastFrame(frames), why));

  // R puts the tools back; unknown keys are not taken
  EXPECT_TRUE(source.handleKey(Qt::Key_R, Qt::NoModifier, true, false));
  EXPECT_EQ(lastFrame(frames).hands, start.hands);
  EXPECT_FALSE(source.handleKey(Qt::Key_P, Qt::NoModifier, true, false));
}

TEST(ManualSource, TSwapsTheActiveHandsForcepsForTheScissorsAndBackWhereTheSceneHasThem) {
  sim::SceneDef withScissors;
  withScissors.scissors = sim::ScissorsDef{};
  ManualSource source;
  source.placeTools(withScissors);
  QSignalSpy frames(&source, &TrackerSource::frameReady);
  QSignalSpy instruments(&source, &ManualSource::instrumentChanged);
  source.start();
  ASSERT_EQ(source.activeHand(), sim::Hand::Right);
  EXPECT_EQ(lastFrame(frames).hand(sim::Hand::Right).instrument, sim::Instrument::Forceps);

  // the jaws half closed, then T: the scissors are taken up open, the other hand keeps its forceps
  source.setClosure(0.5);
  EXPECT_TRUE(source.handleKey(Qt::Key_T, Qt::NoModifier, true, false));
  EXPECT_TRUE(source.handleKey(Qt::Key_T, Qt::NoModifier, false, false));
  EXPECT_TRUE(source.handleKey(Qt::Key_T, Qt::NoModifier, true, true));  // a key repeat swaps nothing
  ASSERT_EQ(instruments.count(), 1);
  EXPECT_EQ(instruments.last().at(1).value<sim::Instrument>(), sim::Instrument::Scissors);
  sim::InputFrame now = lastFrame(frames);
  EXPECT_EQ(now.hand(sim::Hand::Right).instrument, sim::Instrument::Scissors);
  EXPECT_EQ(now.hand(sim::Hand::Right).closure, 0.0);
  EXPECT_EQ(now.hand(sim::Hand::Left).instrument, sim::Instrument::Forceps);

  // the jaw keys close the blades by the same steps
  EXPECT_TRUE(source.handleKey(Qt::Key_C, Qt::NoModifier, true, false));
  EXPECT_DOUBLE_EQ(lastFrame(frames).hand(sim::Hand::Right).closure, ManualSource::kClosureStep);
  EXPECT_EQ(lastFrame(frames).hand(sim::Hand::Right).instrument, sim::Instrument::Scissors);

  // T again: the forceps, open
  EXPECT_TRUE(source.handleKey(Qt::Key_T, Qt::NoModifier, true, false));
  now = lastFrame(frames);
  EXPECT_EQ(now.hand(sim::Hand::Right).instrument, sim::Instrument::Forceps);
  EXPECT_EQ(now.hand(sim::Hand::Right).closure, 0.0);

  // a scene without scissors: T is the map's but swaps nothing
  source.placeTools(sim::SceneDef{});
  const qsizetype before = frames.count();
  EXPECT_TRUE(source.handleKey(Qt::Key_T, Qt::NoModifier, true, false));
  EXPECT_EQ(frames.count(), before);
  EXPECT_FALSE(source.switchActiveInstrument());
  EXPECT_EQ(source.current().hand(sim::Hand::Right).instrument, sim::Instrument::Forceps);
}

TEST(ManualSource, NothingIsEmittedWhenStopped) {
  ManualSource source;
  QSignalSpy frames(&source, &TrackerSource::frameReady);
  source.handleKey(Qt::Key_D, Qt::NoModifier, true, false);
  EXPECT_EQ(frames.count(), 0);
  source.start();
  source.stop();
  const int n = frames.count();
  source.handleKey(Qt::Key_D, Qt::NoModifier, true, false);
  source.moveInView(0.1, 0.1);
  EXPECT_EQ(frames.count(), n);
  EXPECT_FALSE(source.status().connected);
}

TEST(ManualSource, ToolsStartBesideTheCameraTarget) {
  sim::SceneDef def;
  def.camera.target = sim::Vec3(1.0, 2.0, 0.0);
  def.camera.eye = sim::Vec3(1.0, 2.0, 40.0);
  ManualSource source;
  source.placeTools(def);
  const sim::InputFrame& f = source.current();
  EXPECT_LT((f.hand(sim::Hand::Left).position - sim::Vec3(-0.2, 2.0, 0.6)).norm(), 1e-12);
  EXPECT_LT((f.hand(sim::Hand::Right).position - sim::Vec3(2.2, 2.0, 0.6)).norm(), 1e-12);
  // each tool's +x (tip → hinge) points away from the target, outward and up toward the eye
  const sim::Vec3 back = f.hand(sim::Hand::Right).orientation * sim::Vec3::UnitX();
  EXPECT_GT(back.x(), 0.5);
  EXPECT_GT(back.z(), 0.5);
}

// A held needle's circle, 0.8 mm about a centre 0.5 mm ahead of the right tool's tip and
// 0.3 mm to its side: X turns the tool so that every point of the circle (the needle's tip
// among them) stays on the circle, forward by the step; Z turns it back; without a held
// needle neither moves anything.
TEST(ManualSource, XAndZTurnTheToolAlongTheHeldNeedlesCircle) {
  ManualSource source;
  QSignalSpy frames(&source, &TrackerSource::frameReady);
  source.start();
  const sim::HandInput before = source.current().hand(sim::Hand::Right);
  EXPECT_TRUE(source.handleKey(Qt::Key_X, Qt::NoModifier, true, false));
  EXPECT_EQ(source.current().hand(sim::Hand::Right), before) << "no needle held: nothing turns";
  EXPECT_FALSE(source.turnAlongNeedle(10.0));

  HeldNeedleArc arc;
  arc.centre = Eigen::Vector3d(0.5, 0.3, 0.0);
  arc.axis = Eigen::Vector3d(0.0, 0.6, 0.8);
  arc.radius = 0.8;
  source.setHeldNeedle(sim::Hand::Right, arc);
  const auto scene = [](const sim::HandInput& h, const Eigen::Vector3d& inTool) -> Eigen::Vector3d { return h.position + h.orientation * inTool; };
  const Eigen::Vector3d centre = scene(before, arc.centre);
  const Eigen::Vector3d axis = before.orientation * arc.axis;
  // a point of the needle: on the circle, in the tool frame
  const Eigen::Vector3d radial = arc.axis.unitOrthogonal();
  const Eigen::Vector3d needlePoint = arc.centre + arc.radius * radial;
  const Eigen::Vector3d p0 = scene(before, needlePoint);

  EXPECT_TRUE(source.handleKey(Qt::Key_X, Qt::NoModifier, true, false));
  const sim::HandInput turned = lastFrame(frames).hand(sim::Hand::Right);
  EXPECT_LT((scene(turned, arc.centre) - centre).norm(), 1e-12) << "the circle's centre stays";
  EXPECT_LT((turned.orientation * arc.axis - axis).norm(), 1e-12) << "so does its axis";
  const Eigen::Vector3d p1 = scene(turned, needlePoint);
  EXPECT_NEAR((p1 - centre).norm(), arc.radius, 1e-12);
  EXPECT_NEAR((p1 - centre).dot(axis), (p0 - centre).dot(axis), 1e-12);
  const double swept = std::atan2(((p0 - centre).cross(p1 - centre)).dot(axis), (p0 - centre).dot(p1 - centre));
  EXPECT_NEAR(swept * 180.0 / std::numbers::pi, ManualSource::kArcStepDeg, 1e-9) << "forward about the axis";

  EXPECT_TRUE(source.handleKey(Qt::Key_Z, Qt::ShiftModifier, true, false));
  const Eigen::Vector3d p2 = scene(lastFrame(frames).hand(sim::Hand::Right), needlePoint);
  const double back = std::atan2(((p1 - centre).cross(p2 - centre)).dot(axis), (p1 - centre).dot(p2 - centre));
  EXPECT_NEAR(back * 180.0 / std::numbers::pi, -ManualSource::kFineArcStepDeg, 1e-9);
  sim::InputRejection why{};
  EXPECT_TRUE(sim::validateFrame(lastFrame(frames), why));
}

TEST(ManualSource, CAndVCloseAndOpenTheJawsByStepsWithinTheirRange) {
  ManualSource source;
  QSignalSpy frames(&source, &TrackerSource::frameReady);
  source.start();
  for (int k = 0; k < 3; ++k) EXPECT_TRUE(source.handleKey(Qt::Key_C, Qt::NoModifier, true, k > 0));
  EXPECT_NEAR(lastFrame(frames).hand(sim::Hand::Right).closure, 3 * ManualSource::kClosureStep, 1e-12);
  EXPECT_EQ(lastFrame(frames).hand(sim::Hand::Left).closure, 0.0);
  EXPECT_TRUE(source.handleKey(Qt::Key_V, Qt::NoModifier, true, false));
  EXPECT_NEAR(lastFrame(frames).hand(sim::Hand::Right).closure, 2 * ManualSource::kClosureStep, 1e-12);
  for (int k = 0; k < 20; ++k) source.handleKey(Qt::Key_C, Qt::NoModifier, true, true);
  EXPECT_EQ(lastFrame(frames).hand(sim::Hand::Right).closure, 1.0);
  for (int k = 0; k < 20; ++k) source.handleKey(Qt::Key_V, Qt::NoModifier, true, true);
  EXPECT_EQ(lastFrame(frames).hand(sim::Hand::Right).closure, 0.0);
  source.setClosure(0.55);
  EXPECT_EQ(lastFrame(frames).hand(sim::Hand::Right).closure, 0.55);
}

// The working volume is the scene's tissue and tools with a margin: a tip driven far off stops
// at its face, and comes back from there at once.
TEST(ManualSource, TipsStayInTheWorkingVolume) {
  sim::SceneDef def;
  def.camera.eye = sim::Vec3(0.0, 0.0, 40.0);
  def.tissue.model.addNode(sim::Vec3(-3.0, -0.5, -0.5), 1.0);
  def.tissue.model.addNode(sim::Vec3(3.0, 0.5, 0.5), 1.0);
  ManualSource source;
  source.placeTools(def);
  source.setViewBasis(Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ());
  const Eigen::AlignedBox3d& box = source.workingVolume();
  EXPECT_LT((box.min() - sim::Vec3(-4.5, -2.0, -2.0)).norm(), 1e-12);
  EXPECT_LT((box.max() - sim::Vec3(4.5, 2.0, 2.1)).norm(), 1e-12) << "the tools start 0.6 mm up";
  source.start();
  source.moveInView(100.0, -100.0);
  source.moveInDepth(100.0);
  const sim::Vec3 corner = source.current().hand(sim::Hand::Right).position;
  EXPECT_LT((corner - sim::Vec3(4.5, -2.0, 2.1)).norm(), 1e-12);
  source.moveInView(-0.5, 0.0);
  EXPECT_NEAR(source.current().hand(sim::Hand::Right).position.x(), 4.0, 1e-12);
}

}  // namespace
}  // namespace microsim::tracking
