#pragma once
// Automatic pose collection for pivot calibration (pivot_calibration.h). While the tool
// pivots in the divot every pose of its device is offered; a pose is kept only when its
// rotation differs from the last kept one by at least minStepDeg, so a tool held still
// does not fill the set with copies of one pose. The set is ready once it holds
// targetPoses poses AND their spread reaches the solver's minSpreadDeg: poses that do not
// span enough angle are never solved, however many there are.

#include "calibration/pivot_calibration.h"

#include <vector>

namespace microsim::calibration {

struct PivotCollectorOptions {
  double minStepDeg = 1.0;  ///< deg, smallest rotation between two kept poses
  int targetPoses = 100;    ///< poses to keep before solving (≥ solve.minPoses)
  PivotOptions solve;
};

class PivotCollector {
 public:
  explicit PivotCollector(PivotCollectorOptions options = {}) : options_(options) {}

  /// Offers a pose; returns whether it was kept (non-finite and near-duplicate poses are not).
  bool add(const Eigen::Isometry3d& pose);
  void reset();

  int count() const { return static_cast<int>(poses_.size()); }
  double spreadDeg() const { return spreadDeg_; }
  bool spreadEnough() const { return spreadDeg_ >= options_.solve.minSpreadDeg; }
  bool ready() const { return count() >= options_.targetPoses && spreadEnough(); }
  /// Solves with the kept poses (status says whether to accept or redo).
  PivotResult solve() const { return pivotCalibration(poses_, options_.solve); }

  const PivotCollectorOptions& options() const { return options_; }
  const std::vector<Eigen::Isometry3d>& poses() const { return poses_; }

 private:
  PivotCollectorOptions options_;
  std::vector<Eigen::Isometry3d> poses_;
  double spreadDeg_ = 0.0;
};

}  // namespace microsim::calibration
