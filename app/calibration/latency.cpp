#include "calibration/latency.h"

#include <algorithm>
#include <cmath>

namespace microsim::calibration {

namespace {

bool wellFormed(std::span<const SignalSample> s) {
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!std::isfinite(s[i].time) || !std::isfinite(s[i].value)) return false;
    if (i > 0 && !(s[i].time > s[i - 1].time)) return false;
  }
  return true;
}

// linear interpolation of s at times t0 + i h, i = 0..n−1 (t inside s's span)
Eigen::VectorXd resample(std::span<const SignalSample> s, double t0, double h, Eigen::Index n) {
  Eigen::VectorXd out(n);
  std::size_t j = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double t = t0 + static_cast<double>(i) * h;
    while (j + 2 < s.size() && s[j + 1].time < t) ++j;
    const double a = std::clamp((t - s[j].time) / (s[j + 1].time - s[j].time), 0.0, 1.0);
    out(i) = (1.0 - a) * s[j].value + a * s[j + 1].value;
  }
  out.array() -= out.mean();
  return out;
}

// ρ(k) over the overlap of r_i and y_{i+k}
double correlation(const Eigen::VectorXd& r, const Eigen::VectorXd& y, Eigen::Index k) {
  const Eigen::Index n = r.size();
  const Eigen::Index i0 = std::max<Eigen::Index>(0, -k);
  const Eigen::Index i1 = std::min(n, n - k);
  const Eigen::Index len = i1 - i0;
  const auto a = r.segment(i0, len);
  const auto b = y.segment(i0 + k, len);
  const double den = std::sqrt(a.squaredNorm() * b.squaredNorm());
  return den > 0.0 ? a.dot(b) / den : 0.0;
}

}  // namespace

std::vector<SignalSample> speedSignal(std::span<const TimedPosition> positions) {
  std::vector<SignalSample> out;
  for (std::size_t i = 1; i + 1 < positions.size(); ++i) {
    const double dt = positions[i + 1].time - positions[i - 1].time;
    if (!(dt > 0.0)) continue;
    out.push_back({positions[i].time, (positions[i + 1].position - positions[i - 1].position).norm() / dt});
  }
  return out;
}

LatencyResult estimateLatency(std::span<const SignalSample> reference, std::span<const SignalSample> tracked,
                              const LatencyOptions& options) {
  LatencyResult result;
  if (reference.size() < 2 || tracked.size() < 2) return result;
  if (!wellFormed(reference) || !wellFormed(tracked)) {
    result.status = LatencyStatus::NonFinite;
    return result;
  }

  // a common grid over the time both signals cover
  const double h = options.step;
  const double t0 = std::max(reference.front().time, tracked.front().time);
  const double t1 = std::min(reference.back().time, tracked.back().time);
  const auto maxK = static_cast<Eigen::Index>(std::ceil(options.maxLag / h));
  const auto n = static_cast<Eigen::Index>(std::floor((t1 - t0) / h)) + 1;
  if (!(t1 > t0) || n < 2 * maxK + 4) return result;
  const Eigen::VectorXd r = resample(reference, t0, h, n);
  const Eigen::VectorXd y = resample(tracked, t0, h, n);
  if (r.squaredNorm() <= 0.0 || y.squaredNorm() <= 0.0) {
    result.status = LatencyStatus::Flat;
    return result;
  }

  // the best lag on the grid, then a parabola through it and its neighbours
  Eigen::VectorXd rho(2 * maxK + 1);
  for (Eigen::Index k = -maxK; k <= maxK; ++k) rho(k + maxK) = correlation(r, y, k);
  Eigen::Index best = 0;
  rho.maxCoeff(&best);
  double offset = 0.0;
  if (best > 0 && best < rho.size() - 1) {
    const double a = rho(best - 1), b = rho(best), c = rho(best + 1);
    const double den = a - 2.0 * b + c;
    if (den < 0.0) offset = std::clamp(0.5 * (a - c) / den, -0.5, 0.5);
  }
  result.latency = (static_cast<double>(best - maxK) + offset) * h;
  result.correlation = rho(best);
  result.status = result.correlation >= options.minCorrelation ? LatencyStatus::Ok : LatencyStatus::WeakCorrelation;
  return result;
}

}  // namespace microsim::calibration
