#include "microsim/assessment/scoring/arc_metrics.h"
#include "scoring/not_measured.h"

#include <algorithm>
#include <cmath>

namespace microsim::assessment {

namespace {

// true when a grip or release of the suture (the needle is its first nodes) happened in
// (from, to]: the needle may have been re-oriented in between
bool needleRegrippedBetween(const std::vector<sim::SceneEvent>& events, double from, double to) {
  return std::any_of(events.begin(), events.end(), [&](const sim::SceneEvent& e) {
    return (e.kind == sim::SceneEventKind::GripSuture ||
            e.kind == sim::SceneEventKind::ReleaseSuture) &&
           e.time > from && e.time <= to;
  });
}

}  // namespace

double arcDeviationMm(const sim::Vec3& p0, const sim::Vec3& t0, const sim::Vec3& p1,
                      const sim::Vec3& t1, double needleRadius) {
  const sim::Vec3 turn = t0.cross(t1);
  // without a turn the arc allows no displacement (the limit of R·(t₁ − t₀) × n is 0)
  const sim::Vec3 alongArc = turn.norm() > 1e-12
                                 ? sim::Vec3(needleRadius * (t1 - t0).cross(turn.normalized()))
                                 : sim::Vec3::Zero();
  return ((p1 - p0) - alongArc).norm();
}

double needleArcDeviationMm(const Attempt& attempt) {
  if (!std::isfinite(attempt.needleRadius)) return kNaN;
  const std::vector<sim::PierceEvent>& p = attempt.pierces;
  double worst = kNaN;
  for (std::size_t i = 1; i < p.size(); ++i) {
    if (needleRegrippedBetween(attempt.events, p[i - 1].time, p[i].time)) continue;
    const double d =
        arcDeviationMm(p[i - 1].point, p[i - 1].tangent, p[i].point, p[i].tangent,
                       attempt.needleRadius);
    worst = std::isfinite(worst) ? std::max(worst, d) : d;
  }
  return worst;
}

}  // namespace microsim::assessment
