#include "tracking/manual_source.h"

#include <QSignalSpy>

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace microsim::tracking
