#pragma once
// The numeric gate between a decoded pose and the simulation. Each device keeps its last
// accepted pose; a new pose passes only when
//   every entry is finite                                          (else NonFinite),
//   ‖RᵀR − I‖_max ≤ orthonormalTolerance and det R > 0              (else NotOrthonormal),
//   t ≥ t_last                                                     (else TimeBackwards),
//   ‖p − p_last‖ ≤ maxSpeed · (t − t_last) + jumpAllowance         (else TooFast),
// with R the 3 by 3 rotation block, p the translation (mm) and t the source time (s).
// The reference stays the last ACCEPTED pose, so a burst of garbage cannot drag it; a tool
// that was really moved while unseen is accepted again once enough time has passed. The
// tolerance is loose enough for float32 matrices (OpenIGTLink sends float32).

#include "tracking/tracker_types.h"

#include <map>
#include <optional>
#include <string>

namespace microsim::tracking {

struct PoseLimits {
  double maxSpeed = 2000.0;              ///< mm/s, fastest plausible tool motion
  double jumpAllowance = 0.5;            ///< mm, slack added to every speed check (tracker jitter)
  double orthonormalTolerance = 1e-3;    ///< max |entry| of RᵀR − I (float32 round-off ≈ 1e-7)
};

class PoseFilter {
 public:
  explicit PoseFilter(PoseLimits limits = {}) : limits_(limits) {}

  /// Returns no value when the pose passes (and becomes the device's reference), or the reason.
  std::optional<Rejection> check(const RawPose& pose);
  /// A channel value passes when finite and not older than the channel's last one.
  std::optional<Rejection> check(const ChannelValue& value);

  /// Forgets every device (a new connection may restart the source clock).
  void reset() {
    last_.clear();
    lastChannel_.clear();
  }
  const PoseLimits& limits() const { return limits_; }

 private:
  PoseLimits limits_;
  std::map<std::string, RawPose> last_;
  std::map<std::string, double> lastChannel_;
};

/// Max |entry| of RᵀR − I for the rotation block of `m`; +inf when det R ≤ 0.
double orthonormalityError(const Eigen::Matrix4d& m);

}  // namespace microsim::tracking
