#pragma once
// Unit meshes for the marks the draw list places (draw_list.h): scaled and turned by an
// item's model transform, one GPU buffer each serves every reticle, ring and arrow.

#include "gui/shaded_mesh.h"

namespace microsim::gui {

/// Tube radius of the unit ring and of the unit reticle, as fractions of their radius.
inline constexpr float kRingTube = 0.08f;
inline constexpr float kReticleTube = 0.35f;

/// The circle of radius 1 about the origin in the xy plane, as a tube of radius `tube`
/// (kRingTube: a thin ring; kReticleTube: a small marker that leaves its centre open).
ShadedMesh unitRing(float tube = kRingTube, int segments = 32);
/// An arrow from the origin to (0, 0, 1): a shaft of radius 1 to z = 0.7, then a cone of
/// base radius 3 to the point (scale x and y by the line's radius, z by the arrow's length).
ShadedMesh unitArrow(int sides = 10);

}  // namespace microsim::gui
