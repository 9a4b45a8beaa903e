#pragma once
// A scripted stitch: the input frames of one full stitch across a severed vessel, computed,
// not recorded from a hand, so that the shipped recording (resources/recordings/) can be
// regenerated bit for bit and the test knows the exact geometry of every pierce.
//
// Geometry. The ends lie along the vessel axis e_u with the gap centred at c. The stitch
// lies in the plane through the axis at angle φ = π/P from the top (P nodes per ring), where
// the mesh's faces are centred: in that plane the outer wall is the line at w = a_out =
// r cos φ and the lumen wall at w = a_in = (r − t) cos φ (t the wall thickness), both flat,
// with normals ±e_w, e_w = the top direction turned by φ about the axis. The curved needle
// (radius R) turns about the centre C = c + (a_out + h) e_w, h = √(R² − (g/2 + b)²), so
// its tip enters the outer wall a bite b from each cut end (g the gap):
//     tip(ψ) = C + R (sin ψ e_u − cos ψ e_w),   ψ increasing: through end 0, then end 1.
// Entry into end 0 at sin ψ = −(g/2 + b)/R, exit into the lumen where the circle meets
// w = a_in, and symmetrically at end 1: four pierces whose points and angles
// (acos |tangent·e_w|, tangent = (cos ψ, sin ψ) in (e_u, e_w)) stitchPierces() returns.
//
// Phases at the scene's rate (the right hand holds a needle holder, the left a forceps):
//   1. the holder goes to the needle where the scene lays it and closes on it (grip at
//      needle node `gripNode`);
//   2. it carries the needle to the start of the arc, tip above end 0;
//   3. it turns the needle about C through both walls (the four pierces), on until the
//      needle behind its tip stands clear of the far wall;
//   4. the left forceps comes to the needle from the side, slides onto it along its jaws and
//      closes behind the tip; only then does the holder open, draw back along its jaws and go
//      aside (the needle is held throughout, as hands pass it); the forceps turns the needle
//      on along its arc until it is out, and pulls the thread through;
//   5. it opens.
//
// Units: millimetres, seconds, radians.

#include "microsim/sim/scene/recording.h"
#include "microsim/sim/scene/scene_def.h"

#include <optional>
#include <vector>

namespace microsim::sim {

struct StitchScriptDef {
  double biteMm = 0.25;       ///< b: entry distance from each cut end (mm)
  double startDeg = -70.0;    ///< ψ where the pass starts (degrees)
  double endDeg = 85.0;       ///< ψ where the forceps takes the needle and the holder lets go
                              ///< (degrees): node `pullGripNode` then stands clear of the far
                              ///< wall, and the forceps' jaws close on it without touching it
  double passSeconds = 1.55;  ///< duration of phase 3 (s): 1° a frame
  int gripNode = 8;           ///< needle node the holder takes (the swage: its jaws stay clear
                              ///< of the walls the needle turns through)
  int pullGripNode = 1;       ///< needle node the forceps takes
  double pullOutDeg = 190.0;  ///< ψ the forceps turns the needle to
  double pullMm = 3.0;        ///< then the thread is drawn this far along e_w (mm)
};

/// One expected pierce of the pass (stitchPierces).
struct ExpectedPierce {
  Vec3 point = Vec3::Zero();  ///< mm
  double angleDeg = 0.0;
  bool entry = true;
  int end = 0;
};

/// The stitch's geometry in a scene: null when the scene has no severed vessel, no needle
/// or no forceps for both hands, or the needle cannot reach the lumen with this bite.
struct StitchGeometry {
  Vec3 center = Vec3::Zero();  ///< C (mm)
  Vec3 eu = Vec3::UnitX();
  Vec3 ew = Vec3::UnitZ();
  double radius = 0.0;         ///< R (mm)
};
std::optional<StitchGeometry> stitchGeometry(const SceneDef& scene, const StitchScriptDef& def = {});

/// The needle's pose (needle frame → scene) with its tip at ψ (radians) on the pass circle of
/// `g`, its body behind the tip along the circle (see the header essay).
Eigen::Isometry3d needleOnPassCircle(const StitchGeometry& g, double psi);

/// The four pierces a perfect pass makes, in order (entry 0, exit 0, entry 1, exit 1).
std::vector<ExpectedPierce> stitchPierces(const SceneDef& scene, const StitchScriptDef& def = {});

/// The frames of the whole stitch at the scene's rate; empty when stitchGeometry is null.
Recording scriptedStitch(const SceneDef& scene, const StitchScriptDef& def = {});

}  // namespace microsim::sim
