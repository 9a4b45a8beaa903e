#pragma once
// Latency of a tracker: how far a tracked motion lags a reference motion of the same hand
// (a second, faster source moved together with the tool, or a target the tool follows).
// Both motions become scalar signals that do not depend on their frames: the speed
// ‖dp/dt‖ (mm/s, central differences), so the tracker and the reference need no common
// registration. The two signals, sampled at their own irregular times, are resampled by
// linear interpolation onto a uniform grid of step h over the time both cover, their means
// removed, and the normalised cross-correlation
//     ρ(k) = Σ_i r_i y_{i+k} / sqrt(Σ_i r_i² · Σ_i y_{i+k}²)      (sums over the overlap)
// is maximised over lags τ = k h ∈ [−maxLag, maxLag]. A parabola through ρ at the best k
// and its neighbours refines τ below one step. τ > 0: the tracked signal is late.

#include <Eigen/Core>

#include <span>
#include <vector>

namespace microsim::calibration {

struct SignalSample {
  double time = 0.0;   ///< s
  double value = 0.0;  ///< any unit (the same for both signals is not required)
};

struct TimedPosition {
  double time = 0.0;                                   ///< s
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< mm
};

enum class LatencyStatus {
  Ok,
  TooShort,         ///< the signals overlap by less than 2 maxLag + 4 steps
  NonFinite,        ///< NaN/Inf in a sample, or times not increasing
  Flat,             ///< a signal does not vary: move the tool
  WeakCorrelation,  ///< the best ρ is below minCorrelation (the result is still reported)
};

struct LatencyOptions {
  double maxLag = 0.5;           ///< s, largest lag searched either way
  double step = 0.001;           ///< s, grid step h
  double minCorrelation = 0.6;   ///< best ρ accepted as a match
};

struct LatencyResult {
  LatencyStatus status = LatencyStatus::TooShort;
  double latency = 0.0;      ///< s, τ at the peak; > 0 when the tracked signal lags
  double correlation = 0.0;  ///< ρ at the peak, −1..1
  bool ok() const { return status == LatencyStatus::Ok; }
};

/// Speed ‖dp/dt‖ (mm/s) at each interior sample by central differences.
std::vector<SignalSample> speedSignal(std::span<const TimedPosition> positions);

/// τ maximising ρ (see the header), tracked against reference.
LatencyResult estimateLatency(std::span<const SignalSample> reference, std::span<const SignalSample> tracked,
                              const LatencyOptions& options = {});

}  // namespace microsim::calibration
