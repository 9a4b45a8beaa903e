#pragma once
// Microscissors: two straight blades hinged like the forceps' jaws (tools/forceps.h), which
// cut the thread where they close on it.
//
// Tool frame (the forceps' convention): the origin is the tool tip, where the blade tips meet
// when closed; +x runs back along the blades to the pivot at (L, 0, 0), L the blade length;
// the blades open in ±y, each at θ = (1 − closure) · opening off the axis:
//     tip_upper = (L − L cos θ,  L sin θ, 0),   tip_lower = (L − L cos θ, −L sin θ, 0).
//
// Cutting. On the frame the closure reaches ScissorsDef::cutAt from below, the blades cut
// what lay between them as they closed: the triangle (pivot, tip_upper, tip_lower) at the
// closure of the frame before, thickened by the blades' half-thickness plus the thread's
// radius out of the blade plane. Every thread link through that prism is a candidate; each
// run of consecutive candidates is one strand and is cut once, at the link that passes
// nearest the line where the blades meet (y = 0), as a strand is cut where the blades
// cross it. Two strands between the blades (both tails of a knot) are both cut. Needle
// links are steel and are never cut.
//
// What a cut leaves. The cut-end length (MARS10's "cut-end length") is the thread between
// the cut and the nearest anchor along the thread on either side of the cut within its
// piece: a pierce through the wall (later a knot). The needle keeps the piece it is on: the
// thread from its swage to the piece's end is all it has to finish this stitch and tie the
// next, and a cut on that piece that leaves less than NeedleDef::minTieLength leaves a thread
// too short to tie.
//
// Units: millimetres, radians inside (degrees in the def).

#include "microsim/sim/mesh/spring_model.h"
#include "microsim/sim/scene/scene_def.h"

#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace microsim::sim::tools {

/// One cut: the link and where on it (scene frame, mm).
struct ThreadCut {
  int link = -1;
  Vec3 point = Vec3::Zero();
};

/// The blade tips at `closure` in the tool frame: [0] upper, [1] lower (mm).
std::array<Vec3, 2> scissorsBladeTips(const ScissorsDef& def, double closure);

/// Each blade's transform at `closure`, blade frame → scene: [0] upper, [1] lower (mirrored
/// in y, as the forceps' jaws: tools::jawPoses). The blade frame has the blade's tip at the
/// origin and runs back along +x to the pivot at (bladeLength, 0, 0); the cutting edge is
/// that x axis, the blade's back lies towards +y. Its origin is scissorsBladeTips' tip.
std::array<Eigen::Isometry3d, 2> scissorsBladePoses(const ScissorsDef& def, const Eigen::Isometry3d& pose,
                                                    double closure);

/// The cuts of blades at `pose` closing from `closureFrom` to `closureTo` through the chain
/// at positions `chain` (3 by N + 1, links i = (i, i + 1) with alive[i]); links below
/// `firstThreadLink` are the needle's. None unless the closure crosses def.cutAt upwards.
std::vector<ThreadCut> scissorsCuts(const ScissorsDef& def, const Eigen::Isometry3d& pose,
                                    double closureFrom, double closureTo, const Points& chain,
                                    const std::vector<std::uint8_t>& alive, int firstThreadLink,
                                    double threadRadius);

/// The thread between a cut at `cut` and the nearest of `anchorNodes` along the chain on
/// either side of it within its piece, `alive` as before the cut (mm); none when neither side
/// reaches an anchor.
std::optional<double> cutEndLength(const Points& chain, const std::vector<std::uint8_t>& alive,
                                   const ThreadCut& cut, const std::vector<int>& anchorNodes);

/// The thread the needle keeps: from node `swage` along intact links to the end of its piece (mm).
double threadOnNeedle(const Points& chain, const std::vector<std::uint8_t>& alive, int swage);

/// True when link `link` lies on the needle's piece: at or after `swage`, every link from the
/// swage to it intact.
bool onNeedlePiece(const std::vector<std::uint8_t>& alive, int swage, int link);

}  // namespace microsim::sim::tools
