#pragma once
// Per-pierce metrics: pure functions of an Attempt's pierce events and vessel geometry.
//
// A wall passage is a PierceEntry followed by the next PierceExit of the same vessel end
// (the scene reports them in that order as the tip goes in and out of the wall). It is
//   full thickness  when it goes Outer → Inner or Inner → Outer (through the whole wall);
//   partial         otherwise (in and out of the same surface, or through the cut face);
//   a back-wall catch when its entry is on VesselWall::Back (the far half, seen from the
//                   microscope; catching it closes the lumen).
// The entry and exit angles are the scene's: acos |tangent · normal|, 0° = perpendicular.
// The bite is the entry's distance from the cut end along the axis (PierceEvent::biteMm),
// also given in wall thicknesses (DESIGN.md: target ≈ 2–3). The circumferential position
// is the entry point's angle about the vessel's angle axis (attempt.h).
//
// Units: millimetres, degrees.

#include "microsim/assessment/scoring/attempt.h"

#include <vector>

namespace microsim::assessment {

struct PierceMetrics {
  int entry = -1;                ///< index of the entry into Attempt::pierces
  int exit = -1;                 ///< index of the exit, -1 when the tip never came out
  double time = 0.0;             ///< s, the entry's
  int vessel = -1;               ///< index into SceneDef::vessels
  int object = -1;               ///< tissue object (a severed vessel's ends share it)
  int end = -1;                  ///< severed vessel end (0/1), -1 otherwise
  sim::VesselSurface entrySurface = sim::VesselSurface::NotAVessel;
  sim::VesselSurface exitSurface = sim::VesselSurface::NotAVessel;
  double entryAngleDeg = 0.0;    ///< 0 = perpendicular to the wall
  double exitAngleDeg = 0.0;     ///< NaN without an exit
  double biteMm = 0.0;           ///< from the cut edge along the axis (mm)
  double biteWalls = 0.0;        ///< biteMm / wall thickness; NaN without vessel geometry
  double circumferenceDeg = 0.0; ///< [0, 360), 0 toward the microscope; NaN off a vessel
  bool fullThickness = false;
  bool backWall = false;
};

/// Angle of `point` about the vessel's angle axis, in [0, 360) degrees.
double circumferentialAngleDeg(const VesselGeometry& vessel, const sim::Vec3& point);

/// Pairs entries with exits and measures each wall passage, in entry order. Pierces of
/// other tissue (vessel −1) are skipped.
std::vector<PierceMetrics> pierceMetrics(const Attempt& attempt);

}  // namespace microsim::assessment
