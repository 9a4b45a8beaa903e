#pragma once
// The severed vessel the scoring tests pierce by hand: one vessel along +x cut in two, its ends
// (vessels 0 and 1 of one tissue object) with their cut rings at x = ∓0.25 mm, outer radius
// 0.5 mm, wall 0.1 mm thick, the microscope above (+z), so 0° around it is +z and 90° is −y.
#include "microsim/assessment/scoring/attempt.h"

namespace microsim::testing {

inline constexpr double kSeveredVesselRadius = 0.5;  ///< mm
inline constexpr double kSeveredVesselWall = 0.1;    ///< mm

/// An Attempt with the two ends' geometry and nothing else.
inline assessment::Attempt severedVessel() {
  assessment::Attempt a;
  for (int end = 0; end < 2; ++end) {
    assessment::VesselGeometry g;
    g.vessel = end;
    g.object = 0;
    g.end = end;
    g.axis = sim::Vec3(end == 0 ? 1.0 : -1.0, 0.0, 0.0);
    g.cutCentre = sim::Vec3(end == 0 ? -0.25 : 0.25, 0.0, 0.0);
    g.radius = kSeveredVesselRadius;
    g.wallThickness = kSeveredVesselWall;
    g.angleAxis = sim::Vec3::UnitX();
    g.angleZero = sim::Vec3::UnitZ();
    a.vessels.push_back(g);
  }
  return a;
}

}  // namespace microsim::testing
