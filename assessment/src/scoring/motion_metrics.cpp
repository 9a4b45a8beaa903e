#include "microsim/assessment/scoring/motion_metrics.h"
#include "scoring/not_measured.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace microsim::assessment {

namespace {

bool bothTracked(const MotionSample& a, const MotionSample& b) { return a.tracked && b.tracked; }

}  // namespace

double pathLength(const std::vector<MotionSample>& samples) {
  double length = 0.0;
  for (std::size_t i = 1; i < samples.size(); ++i)
    if (bothTracked(samples[i - 1], samples[i]))
      length += (samples[i].position - samples[i - 1].position).norm();
  return length;
}

std::vector<double> speeds(const std::vector<MotionSample>& samples, double dt) {
  std::vector<double> v(samples.size(), 0.0);
  for (std::size_t i = 0; i + 1 < samples.size(); ++i)
    if (bothTracked(samples[i], samples[i + 1]))
      v[i] = (samples[i + 1].position - samples[i].position).norm() / dt;
  if (v.size() >= 2) v.back() = v[v.size() - 2];
  return v;
}

double logDimensionlessJerk(const std::vector<MotionSample>& samples, int begin, int end,
                            double dt) {
  if (end - begin < 4 || !(dt > 0.0)) return kNaN;

  // peak speed and the squared jerk integral from finite differences
  double peak = 0.0;
  for (int k = begin; k + 1 < end; ++k)
    peak = std::max(peak, (samples[k + 1].position - samples[k].position).norm() / dt);
  double jerk2 = 0.0;
  const double dt3 = dt * dt * dt;
  for (int k = begin; k + 3 < end; ++k) {
    const sim::Vec3 j = (samples[k + 3].position - 3.0 * samples[k + 2].position +
                         3.0 * samples[k + 1].position - samples[k].position) /
                        dt3;
    jerk2 += j.squaredNorm() * dt;
  }
  if (!(peak > 0.0) || !(jerk2 > 0.0)) return kNaN;
  const double duration = (end - begin - 1) * dt;
  return -std::log(duration * duration * duration / (peak * peak) * jerk2);
}

std::vector<Movement> segmentMovements(const std::vector<MotionSample>& samples, double dt,
                                       const MotionParams& params) {
  const std::vector<double> v = speeds(samples, dt);
  const int n = static_cast<int>(v.size());

  // runs of speed indices [b, e) at or above the threshold, close ones merged
  std::vector<std::array<int, 2>> runs;
  for (int i = 0; i < n;) {
    if (v[i] < params.movementSpeed) {
      ++i;
      continue;
    }
    int e = i;
    while (e < n && v[e] >= params.movementSpeed) ++e;
    if (!runs.empty() && (i - runs.back()[1]) * dt < params.mergeGapS)
      runs.back()[1] = e;
    else
      runs.push_back({i, e});
    i = e;
  }

  // long enough runs become movements over their samples [b, e + 1)
  std::vector<Movement> out;
  for (const auto& [b, e] : runs) {
    Movement m;
    m.begin = b;
    m.end = std::min(e + 1, static_cast<int>(samples.size()));
    m.duration = (m.end - m.begin - 1) * dt;
    if (m.duration + 1e-12 < params.minMovementS) continue;
    m.peakSpeed = *std::max_element(v.begin() + b, v.begin() + e);
    m.ldlj = logDimensionlessJerk(samples, m.begin, m.end, dt);
    out.push_back(m);
  }
  return out;
}

HandMotion handMotion(const std::vector<MotionSample>& samples, double dt,
                      const MotionParams& params) {
  HandMotion h;
  h.pathLengthMm = pathLength(samples);
  for (double s : speeds(samples, dt))
    if (s < params.idleSpeed) h.idleS += dt;
  h.movements = segmentMovements(samples, dt, params);
  double sum = 0.0;
  int counted = 0;
  for (const Movement& m : h.movements)
    if (std::isfinite(m.ldlj)) {
      sum += m.ldlj;
      ++counted;
    }
  h.meanLdlj = counted > 0 ? sum / counted : kNaN;
  return h;
}

double idleTime(const Attempt& attempt, const MotionParams& params) {
  std::array<std::vector<double>, sim::kHandCount> v;
  std::size_t n = 0;
  for (int h = 0; h < sim::kHandCount; ++h) {
    v[static_cast<std::size_t>(h)] = speeds(attempt.motion[static_cast<std::size_t>(h)],
                                            attempt.stepDt);
    n = std::max(n, v[static_cast<std::size_t>(h)].size());
  }
  double idle = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    bool still = true;
    for (const auto& hv : v) still = still && (i >= hv.size() || hv[i] < params.idleSpeed);
    if (still) idle += attempt.stepDt;
  }
  return idle;
}

bool steppedInput(const Attempt& attempt) {
  int moved = 0;
  int stillAfterwards = 0;
  for (const std::vector<MotionSample>& samples : attempt.motion)
    for (std::size_t i = 1; i < samples.size(); ++i) {
      if (!bothTracked(samples[i - 1], samples[i]) || samples[i].position == samples[i - 1].position)
        continue;
      ++moved;
      if (i + 1 < samples.size() && bothTracked(samples[i], samples[i + 1]) &&
          samples[i + 1].position == samples[i].position)
        ++stillAfterwards;
    }
  return moved > 0 && 2 * stillAfterwards >= moved;
}

int regrasps(const std::vector<sim::SceneEvent>& events) {
  using K = sim::SceneEventKind;
  std::array<bool, sim::kHandCount> released{};
  int count = 0;
  for (const sim::SceneEvent& e : events) {
    if (e.hand < 0 || e.hand >= sim::kHandCount) continue;
    bool& r = released[static_cast<std::size_t>(e.hand)];
    if (e.kind == K::ReleaseTissue || e.kind == K::ReleaseSuture) {
      r = true;
    } else if (e.kind == K::GrabTissue || e.kind == K::GripSuture) {
      if (r) ++count;
      r = false;
    }
  }
  return count;
}

}  // namespace microsim::assessment
