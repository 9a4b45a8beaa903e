#pragma once
// The forceps' jaws against the tissue: a jaw pressed into the wall dents it instead of
// passing through. Each jaw is taken as a tapered capsule around its own axis, from the tip
// (jaw frame origin) to the hinge end (L, 0, 0), its radius growing linearly from the tip's
// to the heel's (the largest distance of the jaw mesh's vertices from the axis near either
// end), which encloses the jaw mesh. Every tissue face within reach of a capsule gets a
// one-sided point spring (point_spring.h) on its point nearest the axis (barycentric weights;
// the nearest points of the axis segment and the face by alternating projections, four
// rounds), anchored at the axis point, pushing along the line from the axis to that point
// with the capsule's radius there as its gap: the jaw, coming from the side the face looks to,
// keeps the face a radius away and pushes it straight away from itself, so that faces meeting
// round the jaw (a cut end's rim) are never pushed against each other. Faces, not nodes: a jaw
// pressed between two nodes dents the face there instead of passing through it.
//
// The scene takes these terms where the faces are at the start of the tissue solve and takes
// them again when the solve has carried the faces onto others (scene.cpp, solveTissue).
//
// Faces with a node a forceps holds are left out (they move with the jaws).
//
// Units: mm, stiffness g/s².

#include "microsim/sim/mesh/point_spring.h"
#include "microsim/sim/mesh/spring_model.h"
#include "microsim/sim/tools/forceps.h"

#include <array>
#include <cstdint>
#include <vector>

namespace microsim::sim::tools {

/// A jaw's capsule in the scene: the axis from tip to heel and the radius at each end (mm).
struct JawCapsule {
  Vec3 tip = Vec3::Zero();
  Vec3 heel = Vec3::Zero();
  double tipRadius = 0.0;
  double heelRadius = 0.0;
};

/// The capsule radii of a jaw mesh at its tip and its heel (mm).
std::array<double, 2> jawRadii(const ForcepsDef& def);

/// Both jaws of `forceps` as capsules, upper first.
std::array<JawCapsule, 2> jawCapsules(const Forceps& forceps);

/// Appends a one-sided spring for every face of `tissue` within `reach` of a jaw's capsule
/// surface at positions x, skipping faces with a node marked in `skip` (held by a forceps:
/// it moves with the jaws).
void appendJawContacts(const Forceps& forceps, const SpringModel& tissue, const Points& x,
                       const std::vector<std::uint8_t>& skip, double reach, double stiffness,
                       std::vector<PointSpring>& out);

}  // namespace microsim::sim::tools
