#include "calibration/registration.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>

namespace microsim::calibration {

namespace {

// per-point distances ‖T a_i − b_i‖, their RMS and max
void pointErrors(const Eigen::Matrix4d& t, const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b,
                 std::vector<double>& errors, double& rms, double& max) {
  errors.clear();
  double sum2 = 0.0;
  max = 0.0;
  for (Eigen::Index i = 0; i < a.cols(); ++i) {
    const Eigen::Vector3d mapped = t.topLeftCorner<3, 3>() * a.col(i) + t.topRightCorner<3, 1>();
    const double e = (mapped - b.col(i)).norm();
    errors.push_back(e);
    sum2 += e * e;
    max = std::max(max, e);
  }
  rms = a.cols() > 0 ? std::sqrt(sum2 / static_cast<double>(a.cols())) : 0.0;
}

}  // namespace

RegistrationResult registerPoints(const Eigen::Matrix3Xd& tracker, const Eigen::Matrix3Xd& scene,
                                  const Eigen::Matrix3Xd& checkTracker, const Eigen::Matrix3Xd& checkScene,
                                  bool withScaling) {
  RegistrationResult r;
  if (tracker.cols() != scene.cols() || checkTracker.cols() != checkScene.cols()) {
    r.status = RegistrationStatus::SizeMismatch;
    return r;
  }
  if (tracker.cols() < 3) return r;
  if (!tracker.allFinite() || !scene.allFinite() || !checkTracker.allFinite() || !checkScene.allFinite()) {
    r.status = RegistrationStatus::NonFinite;
    return r;
  }

  // collinear or coincident fiducials leave a rotation free
  const Eigen::Matrix3Xd centred = tracker.colwise() - tracker.rowwise().mean();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(centred);
  const Eigen::Vector3d sv = svd.singularValues();
  if (!(sv(0) > 0.0) || sv(1) < 1e-6 * sv(0)) {
    r.status = RegistrationStatus::Collinear;
    return r;
  }

  r.transform = Eigen::umeyama(tracker, scene, withScaling);
  r.scale = withScaling ? std::cbrt(r.transform.topLeftCorner<3, 3>().determinant()) : 1.0;
  pointErrors(r.transform, tracker, scene, r.fiducialErrors, r.freRms, r.freMax);
  pointErrors(r.transform, checkTracker, checkScene, r.checkErrors, r.treRms, r.treMax);
  r.checkCount = static_cast<int>(checkTracker.cols());
  r.status = RegistrationStatus::Ok;
  return r;
}

}  // namespace microsim::calibration
