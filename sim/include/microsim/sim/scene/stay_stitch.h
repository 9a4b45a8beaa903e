#pragma once
// A stay stitch already placed: the thread of the scene's needle laid through both ends of a
// severed vessel, as a surgeon leaves it before tying (issue #19: the instrument-tie lesson
// ties its knot on such a stitch). A scene declares it under the needle,
//   "stay_stitch": {"angle_deg": 0, "bite_walls": 2.5, "tail_mm": 2.0}
// and starts with the thread in place and its four holes made.
//
// The path, from the tail to the needle (node N down to the swage):
//   the short tail outside end 0 (about `tail_mm`: one link straight out of the wall, then
//   lying beside the vessel away from the gap); through end 0's wall from its outer surface
//   to its inner one; across the lumen; through end 1's wall from the inside out; one link
//   straight out, then the long end lying beside end 1, and the needle at its end, flat.
// Each wall is crossed obliquely, on a straight line, by the fewest links that are longer
// together than the wall is thick: one where a link is longer than the wall (0.13 mm links on
// its 0.1 mm in the shipped scenes), several on a finer thread, the nodes between on the line
// inside the wall. The node of each hole lies on its surface: a thread node holds one hole
// (suture_constraints.h). The bites are measured on the outer surface from each cut edge;
// the lumen is crossed by whole links, so end 1's bite is end 0's rounded up to the next link
// (at most one link longer).
//
// The holes carry no PierceEvent (the trainee did not make them): they are the suture's
// pierces from the first step, in the order a needle would have made them, so path order
// holds (suture_constraints.h).
//
// Angles follow attempt.h: degrees about end 0's axis (clamp → cut), 0° toward the
// microscope, right-handed. Units: millimetres, degrees.

#include "microsim/sim/suture/suture_model.h"

#include <cstdint>
#include <variant>
#include <vector>

namespace microsim::sim {

struct SceneDef;

struct StayStitchDef {
  double angleDeg = 0.0;   ///< round the vessel pair (see above)
  double biteWalls = 2.5;  ///< end 0's bite from its cut edge, in wall thicknesses (> 0)
  double tailMm = 2.0;     ///< mm of thread left outside end 0 (the tail the forceps takes)
};

enum class StayStitchError : std::uint8_t {
  NoNeedle,           ///< the scene has no needle and thread to lay
  NoSeveredVessel,    ///< no vessel with two ends to stitch
  BiteOutsideTheEnd,  ///< the bite does not fit on the end (or is not positive)
  ThreadTooShort,     ///< the tail and the passage leave the needle less than two links
};

struct LaidStayStitch {
  suture::Points shape;                 ///< every chain node, scene frame (mm)
  std::vector<suture::Pierce> pierces;  ///< the four holes, in the order a needle makes them
};

/// The stitch `stitch` on the scene `def` (its tissue finalised, its needle declared).
std::variant<LaidStayStitch, StayStitchError> layStayStitch(const SceneDef& def,
                                                            const StayStitchDef& stitch);

}  // namespace microsim::sim
