#include "microsim/sim/suture/bending_limit.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace microsim::sim::suture {

int limitBending(Points& x, std::span<const double> rest, const std::vector<std::uint8_t>& alive,
                 std::span<const std::uint8_t> free, double maxTurn) {
  if (!(maxTurn > 0.0 && maxTurn < std::numbers::pi)) return 0;
  const double cosMax = std::cos(maxTurn);
  const int nodes = static_cast<int>(x.cols());
  int count = 0;
  for (int i = 1; i + 1 < nodes; ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (!free[k - 1] || !free[k] || !free[k + 1] || !alive[k - 1] || !alive[k]) continue;
    const double a = rest[k - 1];
    const double b = rest[k];
    const double least2 = a * a + b * b + 2.0 * a * b * cosMax;
    const Vec3 span = x.col(i + 1) - x.col(i - 1);
    const double d2 = span.squaredNorm();
    if (d2 >= least2) continue;
    const double d = std::sqrt(d2);
    // coincident outer nodes: open the turn across the first link's normal plane
    Vec3 dir = d > 0.0 ? Vec3(span / d) : Vec3::Zero();
    if (d == 0.0) {
      const Vec3 link = x.col(i) - x.col(i - 1);
      dir = link.squaredNorm() > 0.0 ? link.unitOrthogonal() : Vec3(Vec3::UnitX());
    }
    const double push = 0.5 * (std::sqrt(least2) - d);
    x.col(i - 1) -= push * dir;
    x.col(i + 1) += push * dir;
    ++count;
  }
  return count;
}

double maxTurnAngle(const Points& x, const std::vector<std::uint8_t>& alive, int first, int last) {
  double most = 0.0;
  for (int i = std::max(first, 1); i < std::min(last + 1, static_cast<int>(x.cols()) - 1); ++i) {
    if (!alive[static_cast<std::size_t>(i - 1)] || !alive[static_cast<std::size_t>(i)]) continue;
    const Vec3 u = x.col(i) - x.col(i - 1);
    const Vec3 v = x.col(i + 1) - x.col(i);
    const double turn = std::atan2(u.cross(v).norm(), u.dot(v));
    most = std::max(most, turn);
  }
  return most;
}

}  // namespace microsim::sim::suture
