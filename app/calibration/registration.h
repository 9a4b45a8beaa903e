#pragma once
// Paired-point registration of the tracker frame to the scene frame. Given fiducials
// touched with a calibrated tool (x_i, tracker frame) and their known scene positions
// (y_i), find the rigid (or similarity) transform T minimising Σ ‖T x_i − y_i‖²; Umeyama's
// closed form (Eigen::umeyama, IEEE PAMI 13(4) 1991) solves it through the SVD of the
// cross-covariance.
//
// Errors (Fitzpatrick's terms), in mm:
//   FRE (fiducial registration error) = sqrt(Σ ‖T x_i − y_i‖² / N), the fit on the
//   fiducials themselves; it is optimistic by construction;
//   TRE (target registration error) on separate check points (never used in the fit),
//   sqrt(Σ ‖T u_j − v_j‖² / M): the error that matters at the anastomosis.
// At least 3 non-collinear fiducials are needed; collinear ones leave the rotation about
// their line free (detected when the second singular value of the centred fiducials is
// below 1e-6 of the first).

#include <Eigen/Core>

#include <vector>

namespace microsim::calibration {

enum class RegistrationStatus {
  Ok,
  TooFewFiducials,  ///< fewer than 3 pairs
  SizeMismatch,     ///< tracker and scene lists (or check lists) differ in length
  NonFinite,        ///< NaN/Inf in a point
  Collinear,        ///< fiducials on one line (or one point)
};

struct RegistrationResult {
  RegistrationStatus status = RegistrationStatus::TooFewFiducials;
  Eigen::Matrix4d transform = Eigen::Matrix4d::Identity();  ///< tracker → scene, homogeneous
  double scale = 1.0;                    ///< similarity scale (1 for rigid)
  double freRms = 0.0;                   ///< mm
  double freMax = 0.0;                   ///< mm
  std::vector<double> fiducialErrors;    ///< mm, ‖T x_i − y_i‖ per fiducial
  double treRms = 0.0;                   ///< mm; 0 with no check points
  double treMax = 0.0;                   ///< mm
  std::vector<double> checkErrors;       ///< mm, per check point
  int checkCount = 0;

  bool ok() const { return status == RegistrationStatus::Ok; }
};

/// Registers tracker points onto scene points (both 3 by N, mm); check points (3 by M,
/// M may be 0) give the TRE. `withScaling`: similarity instead of rigid.
RegistrationResult registerPoints(const Eigen::Matrix3Xd& tracker, const Eigen::Matrix3Xd& scene,
                                  const Eigen::Matrix3Xd& checkTracker, const Eigen::Matrix3Xd& checkScene,
                                  bool withScaling = false);

}  // namespace microsim::calibration
