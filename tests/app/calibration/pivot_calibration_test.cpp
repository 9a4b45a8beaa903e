// Pivot calibration recovers a known tip from noisy synthetic poses, and refuses bad sets.
#include "calibration/pivot_calibration.h"

#include <gtest/gtest.h>

#include <random>

namespace microsim::calibration {
namespace {

// a tool pivoted about `pivot` (tracker frame) with its tip at `tip` (tool frame): tilts up
// to `tiltDeg` about x and y, any spin about the tool axis; translation noise sigma (mm)
std::vector<Eigen::Isometry3d> pivotPoses(const Eigen::Vector3d& tip, const Eigen::Vector3d& pivot, int n, double tiltDeg,
                                          double sigma, unsigned seed, bool spinOnly = false) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> tilt(-tiltDeg * M_PI / 180.0, tiltDeg * M_PI / 180.0);
  std::uniform_real_distribution<double> spin(-M_PI, M_PI);
  std::normal_distribution<double> noise(0.0, sigma);
  std::vector<Eigen::Isometry3d> poses;
  for (int i = 0; i < n; ++i) {
    Eigen::Matrix3d r = Eigen::AngleAxisd(spin(rng), Eigen::Vector3d::UnitZ()).toRotationMatrix();
    if (!spinOnly)
      r = Eigen::AngleAxisd(tilt(rng), Eigen::Vector3d::UnitX()) * Eigen::AngleAxisd(tilt(rng), Eigen::Vector3d::UnitY()) * r;
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = r;
    pose.translation() = pivot - r * tip + Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
    poses.push_back(pose);
  }
  return poses;
}

TEST(PivotCalibration, RecoversTheTipWithinATenthOfAMillimetreAtFiveHundredthsNoise) {
  const Eigen::Vector3d tip(2.0, -3.0, 150.0);
  const Eigen::Vector3d pivot(100.0, 50.0, -30.0);
  for (unsigned seed : {1u, 2u, 3u}) {
    const std::vector<Eigen::Isometry3d> poses = pivotPoses(tip, pivot, 200, 30.0, 0.05, seed);
    const PivotResult r = pivotCalibration(poses);
    EXPECT_EQ(r.status, PivotStatus::Ok);
    EXPECT_LE((r.tipOffset - tip).norm(), 0.1) << r.tipOffset.transpose();
    EXPECT_LE((r.pivot - pivot).norm(), 0.1) << r.pivot.transpose();
    // residual ≈ the noise's 3-D RMS, 0.05 sqrt(3)
    EXPECT_NEAR(r.rmsError, 0.05 * std::sqrt(3.0), 0.02);
    EXPECT_GE(r.maxError, r.rmsError);
    EXPECT_GT(r.spreadDeg, 15.0);
    EXPECT_EQ(r.poseCount, 200);
  }
}

TEST(PivotCalibration, ExactPosesGiveAnExactTip) {
  const Eigen::Vector3d tip(0.5, 0.25, 120.0);
  const PivotResult r = pivotCalibration(pivotPoses(tip, {1, 2, 3}, 20, 40.0, 0.0, 7));
  EXPECT_EQ(r.status, PivotStatus::Ok);
  EXPECT_LT((r.tipOffset - tip).norm(), 1e-9);
  EXPECT_LT(r.rmsError, 1e-9);
}

TEST(PivotCalibration, RefusesSpinOnlyFewAndNonFinitePosesAndLargeResiduals) {
  const Eigen::Vector3d tip(0, 0, 100);
  // spinning about the tool axis: no spread in the worst direction
  const PivotResult spin = pivotCalibration(pivotPoses(tip, {0, 0, 0}, 50, 0.0, 0.0, 3, true));
  EXPECT_EQ(spin.status, PivotStatus::InsufficientSpread);
  EXPECT_LT(spin.spreadDeg, 1.0);

  EXPECT_EQ(pivotCalibration(pivotPoses(tip, {0, 0, 0}, 5, 30.0, 0.0, 4)).status, PivotStatus::TooFewPoses);

  std::vector<Eigen::Isometry3d> poses = pivotPoses(tip, {0, 0, 0}, 20, 30.0, 0.0, 5);
  poses[3].translation().x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(pivotCalibration(poses).status, PivotStatus::NonFinite);

  // a wobbling pivot (2 mm noise) fails the 0.5 mm RMS threshold but still reports a solution
  const PivotResult noisy = pivotCalibration(pivotPoses(tip, {0, 0, 0}, 100, 30.0, 2.0, 6));
  EXPECT_EQ(noisy.status, PivotStatus::RmsAboveThreshold);
  EXPECT_GT(noisy.rmsError, 0.5);
  EXPECT_LT((noisy.tipOffset - tip).norm(), 5.0);
}

}  // namespace
}  // namespace microsim::calibration
