#pragma once
// The gap at a stitch between the two cut ends of a severed vessel: what a stitch is meant
// to close (issue 17: "the facing pair at the stitch goes from 0.50 mm apart to 0.91 mm").
//
// The stitch's angle around the axis: each pierce point minus end 0's axis line, projected
// on the plane normal to the axis and normalised; their mean, normalised, is the direction
// d. On each end, the outer-hull node of the cut ring (the last ring) whose rest position's
// radial direction is nearest d (largest cosine) is that end's lip at the stitch; the gap is
// the distance between the two lips' current positions. At rest it is the scene's gap
// (0.5 mm for the shipped scenes). With no pierce point (or pierce points on the axis) d is
// end 0's sector-0 direction.
//
// The lip at any angle (cutRingLip, for a walk around the whole suture line: scene/leak_test.h):
// the point of a cut ring's hull at the direction d, between the two nodes whose rest radial
// directions flank d, linear in the angle between them: at a node's own angle it is that node.
//
// Units: millimetres.

#include "microsim/sim/mesh/spring_model.h"
#include "microsim/sim/mesh/vessel.h"

#include <array>
#include <optional>
#include <vector>

namespace microsim::sim {
struct SceneVessel;
}

namespace microsim::sim::collide {

struct EndGap {
  double gap = 0.0;      ///< mm, between the two lips now
  double restGap = 0.0;  ///< mm, between them at rest
  int node0 = -1;        ///< end 0's lip node (tissue index)
  int node1 = -1;        ///< end 1's lip node
  Vec3 direction = Vec3::Zero();  ///< the stitch's unit direction d, normal to the axis
};

/// The gap at the stitch through `piercePoints` (mm) between ends 0 and 1 among `vessels`,
/// with tissue positions x (3 by #N, mm); none when the vessels have no end 0 and end 1.
std::optional<EndGap> endGapAtStitch(const SpringModel& model, const Points& x,
                                     const std::vector<SceneVessel>& vessels,
                                     const std::vector<Vec3>& piercePoints);

/// End 0 and end 1 of the severed vessel among `vessels` (the last of each), null where missing.
std::array<const SceneVessel*, 2> severedEnds(const std::vector<SceneVessel>& vessels);

/// The lip of vessel end `v` on `hull` toward unit direction d (normal to its axis) at tissue
/// positions x (3 by #N, mm): the cut ring's point at d's angle (see above), mm.
Vec3 cutRingLip(const SpringModel& model, const Points& x, const SceneVessel& v, const Vec3& d,
                VesselHull hull);

}  // namespace microsim::sim::collide
