#include "microsim/assessment/scoring/pierce_metrics.h"
#include "scoring/not_measured.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace microsim::assessment {

namespace {

bool throughWall(sim::VesselSurface in, sim::VesselSurface out) {
  using S = sim::VesselSurface;
  return (in == S::Outer && out == S::Inner) || (in == S::Inner && out == S::Outer);
}

}  // namespace

double circumferentialAngleDeg(const VesselGeometry& vessel, const sim::Vec3& point) {
  const sim::Vec3 rel = point - vessel.cutCentre;
  const sim::Vec3 side = vessel.angleAxis.cross(vessel.angleZero);
  double deg = std::atan2(rel.dot(side), rel.dot(vessel.angleZero)) * 180.0 / std::numbers::pi;
  if (deg < 0.0) deg += 360.0;
  return deg >= 360.0 ? 0.0 : deg;
}

std::vector<PierceMetrics> pierceMetrics(const Attempt& attempt) {
  std::vector<PierceMetrics> out;
  const auto geometry = [&](int vessel) -> const VesselGeometry* {
    for (const VesselGeometry& g : attempt.vessels)
      if (g.vessel == vessel) return &g;
    return nullptr;
  };

  for (std::size_t i = 0; i < attempt.pierces.size(); ++i) {
    const sim::PierceEvent& p = attempt.pierces[i];
    if (p.vessel < 0) continue;

    // an entry opens a passage
    if (p.entry) {
      PierceMetrics m;
      m.entry = static_cast<int>(i);
      m.time = p.time;
      m.vessel = p.vessel;
      m.end = p.end;
      m.entrySurface = p.surface;
      m.entryAngleDeg = p.angleDeg;
      m.exitAngleDeg = kNaN;
      m.biteMm = p.biteMm;
      m.backWall = p.wall == sim::VesselWall::Back;
      const VesselGeometry* g = geometry(p.vessel);
      m.object = g ? g->object : -1;
      m.biteWalls = g && g->wallThickness > 0.0 ? p.biteMm / g->wallThickness : kNaN;
      m.circumferenceDeg = g ? circumferentialAngleDeg(*g, p.point) : kNaN;
      out.push_back(m);
      continue;
    }

    // an exit closes the latest open passage of its vessel
    for (auto it = out.rbegin(); it != out.rend(); ++it) {
      if (it->vessel != p.vessel || it->exit >= 0) continue;
      it->exit = static_cast<int>(i);
      it->exitSurface = p.surface;
      it->exitAngleDeg = p.angleDeg;
      it->fullThickness = throughWall(it->entrySurface, p.surface);
      break;
    }
  }
  return out;
}

}  // namespace microsim::assessment
