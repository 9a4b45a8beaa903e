#pragma once
// The plane behind the tissue, the microscope's drape: perpendicular to the scene camera's
// view, 1 mm past the tissue's farthest node as the camera first sees it, 80 mm square; and
// the planar projection that casts the scene's shadow on it along a light from above and to
// the side (the shadow is the depth cue the plane exists for).
//
// Units: millimetres.

#include "gui/shaded_mesh.h"

#include "microsim/sim/scene/scene_def.h"

#include <QMatrix4x4>
#include <QVector4D>

namespace microsim::gui {

struct BackgroundPlane {
  ShadedMesh mesh;    ///< scene frame
  QMatrix4x4 shadow;  ///< scene point → its shadow on the plane
};

BackgroundPlane backgroundPlane(const sim::SceneDef& def);

/// M = (n·L) I − L ⊗ P: projects onto the plane P = (n, d) along the directional light L.
QMatrix4x4 planarShadow(const QVector4D& plane, const QVector4D& light);

}  // namespace microsim::gui
