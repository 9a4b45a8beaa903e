#pragma once
// The tools' meshes in their own frames, read once from the scene's definition: a forceps'
// jaw (the scene's jaw mesh, jaw frame: tip at the origin, body along +x; tools/forceps.h)
// and the scalpel (tools/scalpel.h: the blade [0, length] × {0} × [0, height] of its frame,
// given a thickness, and a handle behind it along +x), and the microscissors
// (tools/microscissors.h: each blade in its blade frame, tip at the origin, cutting edge along
// +x to the pivot, its back towards +y; a shaft behind the pivot in the tool frame).
//
// Units: millimetres.

#include "gui/shaded_mesh.h"

#include "microsim/sim/scene/scene_def.h"

namespace microsim::gui {

/// mm: how thick the scalpel's blade is drawn (the engine's blade is a plane).
inline constexpr float kBladeThickness = 0.03f;
/// mm: the handle's length and radius behind the blade's heel.
inline constexpr float kScalpelHandleLength = 8.0f;
inline constexpr float kScalpelHandleRadius = 0.2f;

/// mm: how wide a scissors blade is drawn, from its cutting edge to its back (the engine's
/// blade is its edge and a thickness).
inline constexpr float kScissorsBladeWidth = 0.07f;
/// mm: the shaft's length and radius behind the scissors' pivot.
inline constexpr float kScissorsShaftLength = 8.0f;
inline constexpr float kScissorsShaftRadius = 0.15f;

/// One jaw of `def`, jaw frame, with area-weighted vertex normals.
ShadedMesh jawMesh(const sim::ForcepsDef& def);
/// The scalpel of `def`, blade frame.
ShadedMesh scalpelMesh(const sim::ScalpelDef& def);
/// One scissors blade of `def`, blade frame: [0, bladeLength] along x, [0, kScissorsBladeWidth]
/// in y, the engine's thickness in z (the lower blade is drawn mirrored, as the engine poses it).
ShadedMesh scissorsBladeMesh(const sim::ScissorsDef& def);
/// The scissors' shaft, tool frame: a tube along +x from the pivot.
ShadedMesh scissorsShaftMesh(const sim::ScissorsDef& def);

}  // namespace microsim::gui
