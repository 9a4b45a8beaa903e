#pragma once
// Pivot calibration of a tool tip. The tool is pivoted about its tip held still in a
// divot; every tracked pose (R_i, t_i) of the tool's marker frame then satisfies
//     R_i p_tip + t_i = p_pivot,
// with p_tip the tip in the tool frame and p_pivot the divot in the tracker frame (mm).
// Stacking N poses gives the algebraic least-squares problem
//     [R_1 −I; …; R_N −I] (p_tip; p_pivot) = (−t_1; …; −t_N)      (3N by 6)
// solved by column-pivoted QR. Residual of pose i: e_i = ‖R_i p_tip + t_i − p_pivot‖;
// RMS error = sqrt(Σ e_i² / N).
//
// Pose spread. The system has full rank only when the rotations vary about two axes
// perpendicular to the tool: spinning the tool about its own axis leaves the tip's
// position along that axis unknown. The spread is measured in the worst direction: with
// R̄ the mean of the R_i (entrywise) and σ the smallest singular value of the stacked
// (R_i − R̄) (3N by 3), s = σ / sqrt(N) is the RMS displacement of a unit vector in that
// direction, and spreadDeg = 2 asin(min(1, s / 2)) the rotation angle with the same
// chord. A spin about the tool axis has spreadDeg ≈ 0; tilts of ±θ about two axes give a
// spread of the order of θ.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <span>

namespace microsim::calibration {

enum class PivotStatus {
  Ok,
  TooFewPoses,          ///< fewer than PivotOptions::minPoses
  NonFinite,            ///< a pose had NaN/Inf
  InsufficientSpread,   ///< spreadDeg below minSpreadDeg: pivot more (the solution is still reported)
  RmsAboveThreshold,    ///< RMS error above maxRms: redo (the solution is still reported)
};

struct PivotOptions {
  int minPoses = 8;              ///< poses needed before solving
  double minSpreadDeg = 15.0;    ///< deg, smallest accepted pose spread (see header)
  double maxRms = 0.5;           ///< mm, largest accepted RMS error
};

struct PivotResult {
  PivotStatus status = PivotStatus::TooFewPoses;
  Eigen::Vector3d tipOffset = Eigen::Vector3d::Zero();  ///< tip in the tool frame, mm
  Eigen::Vector3d pivot = Eigen::Vector3d::Zero();      ///< pivot point in the tracker frame, mm
  double rmsError = 0.0;    ///< mm, RMS of e_i
  double maxError = 0.0;    ///< mm, max of e_i
  double spreadDeg = 0.0;   ///< deg, pose spread in the worst direction
  int poseCount = 0;

  bool accepted() const { return status == PivotStatus::Ok; }
};

/// Pivot calibration from tool → tracker poses (rigid, translation in mm).
PivotResult pivotCalibration(std::span<const Eigen::Isometry3d> poses, const PivotOptions& options = {});

/// Pose spread (deg) of a set of rotations, as defined in the header.
double poseSpreadDeg(std::span<const Eigen::Isometry3d> poses);

}  // namespace microsim::calibration
