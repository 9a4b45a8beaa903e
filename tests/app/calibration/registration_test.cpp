// Paired-point registration recovers a known transform; FRE on the fiducials, TRE on check points.
#include "calibration/registration.h"

#include "calibration/setup_calibration.h"

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include <random>

namespace microsim::calibration {
namespace {

Eigen::Matrix4d knownTransform(double scale = 1.0) {
  Eigen::Matrix4d t = Eigen::Matrix4d::Identity();
  t.topLeftCorner<3, 3>() = scale * Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  t.topRightCorner<3, 1>() = Eigen::Vector3d(-250.0, 40.0, 1200.0);
  return t;
}

Eigen::Matrix3Xd apply(const Eigen::Matrix4d& t, const Eigen::Matrix3Xd& p) {
  return (t.topLeftCorner<3, 3>() * p).colwise() + Eigen::Vector3d(t.topRightCorner<3, 1>());
}

TEST(Registration, RecoversAKnownRigidTransformExactly) {
  Eigen::Matrix3Xd tracker(3, 4);
  tracker << 0, 50, 0, 10, 0, 0, 40, 30, 0, 0, 0, 25;
  Eigen::Matrix3Xd check(3, 2);
  check << 20, 5, 20, 35, 10, 12;
  const Eigen::Matrix4d t = knownTransform();
  const RegistrationResult r = registerPoints(tracker, apply(t, tracker), check, apply(t, check));
  ASSERT_EQ(r.status, RegistrationStatus::Ok);
  EXPECT_LT((r.transform - t).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT(r.freRms, 1e-9);
  EXPECT_LT(r.treMax, 1e-9);
  EXPECT_EQ(r.scale, 1.0);
  EXPECT_EQ(r.fiducialErrors.size(), 4u);
  EXPECT_EQ(r.checkCount, 2);
}

TEST(Registration, NoisyFiducialsGiveFreAndTreOfTheNoiseOrder) {
  std::mt19937 rng(11);
  std::normal_distribution<double> noise(0.0, 0.1);
  Eigen::Matrix3Xd tracker(3, 6);
  tracker << 0, 60, 0, 0, 60, 30, 0, 0, 60, 0, 60, 30, 0, 0, 0, 60, 30, 60;
  const Eigen::Matrix4d t = knownTransform();
  Eigen::Matrix3Xd scene = apply(t, tracker);
  for (Eigen::Index i = 0; i < scene.size(); ++i) scene.data()[i] += noise(rng);
  Eigen::Matrix3Xd check(3, 3);
  check << 30, 20, 10, 30, 40, 20, 30, 20, 40;
  const RegistrationResult r = registerPoints(tracker, scene, check, apply(t, check));
  ASSERT_TRUE(r.ok());
  EXPECT_GT(r.freRms, 0.01);
  EXPECT_LT(r.freRms, 0.3);
  EXPECT_LT(r.treRms, 0.3);  // inside the fiducials' hull the target error stays at the noise level
  EXPECT_GE(r.freMax, r.freRms);
}

TEST(Registration, SimilarityRecoversTheScale) {
  Eigen::Matrix3Xd tracker(3, 4);
  tracker << 0, 50, 0, 10, 0, 0, 40, 30, 0, 0, 0, 25;
  const Eigen::Matrix4d t = knownTransform(0.25);
  const RegistrationResult r = registerPoints(tracker, apply(t, tracker), Eigen::Matrix3Xd(3, 0), Eigen::Matrix3Xd(3, 0), true);
  ASSERT_TRUE(r.ok());
  EXPECT_NEAR(r.scale, 0.25, 1e-12);
  EXPECT_LT((r.transform - t).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_EQ(r.treRms, 0.0);
}

TEST(Registration, RefusesTooFewCollinearMismatchedAndNonFinitePoints) {
  const Eigen::Matrix3Xd none(3, 0);
  Eigen::Matrix3Xd two(3, 2);
  two << 0, 1, 0, 1, 0, 1;
  EXPECT_EQ(registerPoints(two, two, none, none).status, RegistrationStatus::TooFewFiducials);
  Eigen::Matrix3Xd line(3, 4);
  line << 0, 1, 2, 3, 0, 2, 4, 6, 0, 3, 6, 9;
  EXPECT_EQ(registerPoints(line, line, none, none).status, RegistrationStatus::Collinear);
  Eigen::Matrix3Xd three(3, 3);
  three << 0, 1, 0, 0, 0, 1, 0, 0, 0;
  EXPECT_EQ(registerPoints(three, line, none, none).status, RegistrationStatus::SizeMismatch);
  Eigen::Matrix3Xd bad = three;
  bad(1, 1) = std::numeric_limits<double>::infinity();
  EXPECT_EQ(registerPoints(bad, three, none, none).status, RegistrationStatus::NonFinite);
}

TEST(SetupCalibration, AppliesTipOffsetRegistrationAndMotionScaling) {
  sim::InputFrame tracker;
  tracker.time = 2.0;
  sim::HandInput& left = tracker.hand(sim::Hand::Left);
  left.tracked = true;
  left.position = Eigen::Vector3d(10, 0, 0);
  left.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  left.closure = 0.3;

  SetupCalibration c;
  c.tipOffset[0] = Eigen::Vector3d(5, 0, 0);  // along the tool's x, which points along tracker y
  c.trackerToScene.topRightCorner<3, 1>() = Eigen::Vector3d(0, 0, 100);
  c.scaling.handPerScene = 5.0;
  c.scaling.anchor = Eigen::Vector3d(0, 0, 100);

  const sim::InputFrame scene = toScene(tracker, c);
  // tip (10, 5, 0) → registered (10, 5, 100) → scaled about the anchor: (2, 1, 100)
  EXPECT_LT((scene.hand(sim::Hand::Left).position - Eigen::Vector3d(2, 1, 100)).norm(), 1e-12);
  EXPECT_NEAR(scene.hand(sim::Hand::Left).orientation.angularDistance(left.orientation), 0.0, 1e-12);
  EXPECT_EQ(scene.hand(sim::Hand::Left).closure, 0.3);
  EXPECT_EQ(scene.time, 2.0);
  // an untracked hand is left alone
  EXPECT_EQ(scene.hand(sim::Hand::Right), tracker.hand(sim::Hand::Right));
}

}  // namespace
}  // namespace microsim::calibration
