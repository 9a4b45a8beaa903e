#pragma once
// A scripted back-wall catch: the classic error of micro-anastomosis, as a recording the
// end-product check must find (resources/recordings/back_wall_catch.msrec). Meaning to take
// the front wall of end 0, the needle goes on through the lumen and out through the far
// (back) wall of the same end, so the thread sews the front wall to the back and would close
// the lumen once tied.
//
// Geometry. The pass lies in the cross-section of end 0 a bite b from its cut. In that plane
// the wall is a ring about the axis point P; angles θ are read from the top (the vessel's
// up, as in stitch_script.h) toward the side s that faces away from the microscope, so that
// θ near 0 is the front wall and θ past about 80° the back wall as the scene judges it
// (PierceEvent::wall). The needle's circle (its radius R) passes through the outer wall at
// θ_entry and θ_catch with its centre outside the vessel, so the arc between them runs
// through the lumen:
//     C = M + √(R² − h²) n,   M the chord's midpoint, h half its length, n ⊥ chord away from P.
// The pierces it makes, in order: into the front wall's outer surface, out of its inner one,
// into the back wall's inner surface (the catch), out of its outer one.
//
// The hands are those of the scripted stitch (pass_recorder.h): the holder turns the needle
// through, the forceps takes it beside the back wall and pulls the thread out along CP.
//
// Units: millimetres, seconds, degrees.

#include "microsim/sim/scene/recording.h"
#include "microsim/sim/scene/scene_def.h"
#include "microsim/sim/scene/stitch_script.h"

#include <optional>

namespace microsim::sim {

struct BackWallCatchDef {
  double biteMm = 0.3;       ///< b: the cross-section's distance from end 0's cut (mm)
  double entryDeg = -20.0;   ///< θ where the tip enters the front wall
  double catchDeg = 105.0;   ///< θ where it leaves through the back wall
  double leadDeg = 20.0;     ///< the pass starts this far (ψ) before the entry
  double clearDeg = 40.0;    ///< and ends this far past the catch: node `pullGripNode` stands
                             ///< clear of the back wall for the forceps' jaws
  double passSeconds = 1.4;  ///< about 1° of ψ a frame
  int gripNode = 8;          ///< the swage, as in the stitch
  int pullGripNode = 1;
  double pullMm = 3.0;  ///< the thread is drawn this far out along CP (mm)
};

/// The catch's circle in a scene: null without a severed vessel, a curved needle and two
/// forceps, or when the needle is too small to span the chord.
std::optional<StitchGeometry> backWallCatchGeometry(const SceneDef& scene,
                                                    const BackWallCatchDef& def = {});

/// The frames of the whole pass at the scene's rate; empty when the geometry is null.
Recording scriptedBackWallCatch(const SceneDef& scene, const BackWallCatchDef& def = {});

}  // namespace microsim::sim
