#include "calibration/pivot_calibration.h"

#include <Eigen/QR>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>

namespace microsim::calibration {

double poseSpreadDeg(std::span<const Eigen::Isometry3d> poses) {
  const auto n = static_cast<Eigen::Index>(poses.size());
  if (n < 2) return 0.0;
  Eigen::Matrix3d mean = Eigen::Matrix3d::Zero();
  for (const Eigen::Isometry3d& p : poses) mean += p.linear();
  mean /= static_cast<double>(n);
  Eigen::MatrixXd stacked(3 * n, 3);
  for (Eigen::Index i = 0; i < n; ++i) stacked.block<3, 3>(3 * i, 0) = poses[static_cast<std::size_t>(i)].linear() - mean;
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(stacked);
  const double s = svd.singularValues()(2) / std::sqrt(static_cast<double>(n));
  return 2.0 * std::asin(std::min(1.0, s / 2.0)) * 180.0 / M_PI;
}

PivotResult pivotCalibration(std::span<const Eigen::Isometry3d> poses, const PivotOptions& options) {
  PivotResult r;
  r.poseCount = static_cast<int>(poses.size());
  if (r.poseCount < std::max(options.minPoses, 2)) return r;
  for (const Eigen::Isometry3d& p : poses) {
    if (!p.matrix().allFinite()) {
      r.status = PivotStatus::NonFinite;
      return r;
    }
  }

  // the stacked system [R_i −I] (p_tip; p_pivot) = −t_i
  const auto n = static_cast<Eigen::Index>(poses.size());
  Eigen::MatrixXd a(3 * n, 6);
  Eigen::VectorXd b(3 * n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Isometry3d& p = poses[static_cast<std::size_t>(i)];
    a.block<3, 3>(3 * i, 0) = p.linear();
    a.block<3, 3>(3 * i, 3) = -Eigen::Matrix3d::Identity();
    b.segment<3>(3 * i) = -p.translation();
  }
  const Eigen::VectorXd x = a.colPivHouseholderQr().solve(b);
  r.tipOffset = x.head<3>();
  r.pivot = x.tail<3>();

  // residuals per pose
  double sum2 = 0.0;
  for (const Eigen::Isometry3d& p : poses) {
    const double e = (p.linear() * r.tipOffset + p.translation() - r.pivot).norm();
    sum2 += e * e;
    r.maxError = std::max(r.maxError, e);
  }
  r.rmsError = std::sqrt(sum2 / static_cast<double>(n));
  r.spreadDeg = poseSpreadDeg(poses);

  if (r.spreadDeg < options.minSpreadDeg)
    r.status = PivotStatus::InsufficientSpread;
  else if (r.rmsError > options.maxRms)
    r.status = PivotStatus::RmsAboveThreshold;
  else
    r.status = PivotStatus::Ok;
  return r;
}

}  // namespace microsim::calibration
