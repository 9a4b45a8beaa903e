#pragma once
// The forceps' jaws against the tissue: a jaw pressed into the wall dents it instead of
// passing through. Each jaw is taken as a tapered capsule around its own axis, from the tip
// (jaw frame origin) to the hinge end (L, 0, 0), its radius growing linearly from the tip's
// to the heel's (the largest distance of the jaw mesh's vertices from the axis near either
// end), which encloses the jaw mesh. A tissue node within reach of a capsule gets a
// one-sided point spring (point_spring.h) anchored on the capsule's axis with the normal
// from the axis to the node and the capsule's radius there as its gap, so the node is kept
// on the capsule's surface while pressed.
//
// Nodes the forceps holds are left out (they move with the jaws), as are fixed nodes.
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

/// Appends a one-sided spring for every node of `nodes` within `reach` of a jaw's capsule
/// surface, skipping nodes marked in `skip` (fixed, held by a forceps).
void appendJawContacts(const Forceps& forceps, const Points& x, const std::vector<int>& nodes,
                       const std::vector<std::uint8_t>& skip, double reach, double stiffness,
                       std::vector<PointSpring>& out);

}  // namespace microsim::sim::tools
