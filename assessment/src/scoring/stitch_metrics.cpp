#include "microsim/assessment/scoring/stitch_metrics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace microsim::assessment {

namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

double wrap360(double deg) {
  double d = std::fmod(deg, 360.0);
  if (d < 0.0) d += 360.0;
  return d >= 360.0 ? 0.0 : d;
}

// circular mean of two angles (degrees)
double meanAngleDeg(double a, double b) {
  const double x = std::cos(a * kDegToRad) + std::cos(b * kDegToRad);
  const double y = std::sin(a * kDegToRad) + std::sin(b * kDegToRad);
  if (std::abs(x) < 1e-12 && std::abs(y) < 1e-12) return wrap360(a);
  return wrap360(std::atan2(y, x) / kDegToRad);
}

}  // namespace

double angularDistanceDeg(double aDeg, double bDeg) {
  const double d = wrap360(aDeg - bDeg);
  return d > 180.0 ? 360.0 - d : d;
}

std::vector<StitchMetrics> stitchMetrics(const std::vector<PierceMetrics>& passages) {
  std::vector<StitchMetrics> out;
  for (std::size_t i = 0; i + 1 < passages.size();) {
    const PierceMetrics& a = passages[i];
    const PierceMetrics& b = passages[i + 1];
    const bool pair = a.object >= 0 && a.object == b.object && a.end >= 0 && b.end >= 0 &&
                      a.end != b.end;
    if (!pair) {
      ++i;
      continue;
    }
    StitchMetrics s;
    s.first = static_cast<int>(i);
    s.second = static_cast<int>(i + 1);
    s.time = a.time;
    s.biteAMm = a.biteMm;
    s.biteBMm = b.biteMm;
    s.symmetryMm = std::abs(a.biteMm - b.biteMm);
    s.positionDeg = meanAngleDeg(a.circumferenceDeg, b.circumferenceDeg);
    s.spacingDeg = out.empty() ? std::numeric_limits<double>::quiet_NaN()
                               : angularDistanceDeg(s.positionDeg, out.back().positionDeg);
    s.fullThickness = a.fullThickness && b.fullThickness;
    out.push_back(s);
    i += 2;
  }
  return out;
}

std::optional<double> triangulationErrorDeg(const std::vector<StitchMetrics>& stitches) {
  if (stitches.size() < 3) return std::nullopt;
  std::array<double, 3> p{stitches[0].positionDeg, stitches[1].positionDeg,
                          stitches[2].positionDeg};
  for (double& d : p) d = wrap360(d);
  std::sort(p.begin(), p.end());
  const std::array<double, 3> arcs{p[1] - p[0], p[2] - p[1], 360.0 - p[2] + p[0]};
  double worst = 0.0;
  for (double arc : arcs) worst = std::max(worst, std::abs(arc - 120.0));
  return worst;
}

}  // namespace microsim::assessment
