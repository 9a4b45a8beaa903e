#pragma once
// The tools' meshes in their own frames, read once from the scene's definition: a forceps'
// jaw (the scene's jaw mesh, jaw frame: tip at the origin, body along +x; tools/forceps.h)
// and the scalpel (tools/scalpel.h: the blade [0, length] × {0} × [0, height] of its frame,
// given a thickness, and a handle behind it along +x).
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

/// One jaw of `def`, jaw frame, with area-weighted vertex normals.
ShadedMesh jawMesh(const sim::ForcepsDef& def);
/// The scalpel of `def`, blade frame.
ShadedMesh scalpelMesh(const sim::ScalpelDef& def);

}  // namespace microsim::gui
