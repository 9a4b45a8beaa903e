#pragma once
// The tissue as the viewport draws it: the scene's tissue nodes as vertices, plus a copy of
// each node of a vessel's end annuli, so the cut face of the wall can have a colour and a
// shading of its own (a node on the rim is shared by the outer wall, the lumen and the end
// face; without copies the three would blend into one colour there and the wall's thickness
// would not read).
//
// Each vertex carries what the tissue shader (resources/shaders/shaded.frag) needs besides
// its position and normal:
//   - a colour (linear RGB): the outer wall, the lumen darkened by ambient occlusion the
//     deeper it lies from the open cut end (one looks into a tube: light reaches its mouth,
//     not its depth), or the paler cut face;
//   - a surface point, where the vertex sat at rest in its vessel's own frame (mm: along the
//     axis from the clamped end, then across it), and the layer it belongs to. The shader's
//     procedural wall texture (fibres, vasa vasorum, fine grain) is a function of that point,
//     so it stays on the tissue as the tissue moves and has no seam round the vessel.
// Tissue that is no vessel keeps its scene position as its surface point and the outer
// layer.
//
// A scene may ask for a smooth surface ("surface": {"subdivision": n}, mesh/smooth_surface.h):
// the drawn vertices are then those of the coarse tissue refined n times, on a smooth surface
// through every node, and their normals come from the refined triangles. Everything above holds
// for them as for nodes: a refined vertex lies in one coarse triangle and takes its part.
//
// Built once per scene on the GUI thread, without GL
// (tests/app/gui/render/tissue_surface_test.cpp).
//
// Units: millimetres; colours linear RGB.

#include "gui/shaded_mesh.h"

#include "microsim/sim/scene/render_snapshot.h"
#include "microsim/sim/scene/scene_def.h"

#include <QVector3D>

#include "microsim/sim/mesh/smooth_surface.h"

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace microsim::gui {

/// Which part of the tissue a vertex belongs to; the shader's `layer` (a float) is its value.
enum class TissueLayer : std::uint8_t {
  OuterWall = 0,  ///< the adventitia, and tissue that is no vessel
  Lumen = 1,      ///< the inner wall
  CutFace = 2,    ///< the wall's end faces, where its thickness shows
};

/// The wall's cut face: paler than the outer wall (the media seen in section).
inline const QVector3D kVesselCutFace(0.90f, 0.55f, 0.50f);

/// How dark the lumen gets where it is deepest (fraction of its colour kept).
inline constexpr float kLumenDeepest = 0.35f;

struct TissueSurface {
  std::vector<std::uint32_t> indices;  ///< three per triangle, into the vertices below
  /// The point each vertex shows: a tissue node, or with `smooth` a vertex of the smooth surface.
  std::vector<int> source;
  std::vector<float> colours;          ///< 3 per vertex, linear RGB, occlusion applied
  std::vector<float> surface;          ///< 4 per vertex: surface point (x, y, z) and layer
  /// The smooth surface the vertices lie on; empty when the scene draws its triangles as they are.
  std::shared_ptr<const sim::SmoothSurface> smooth;
  /// With `smooth`: `indices` as triangles, for the normals, and the placing's buffers.
  std::vector<std::array<int, 3>> triangles;
  std::vector<float> refined;
  std::vector<float> positions;
  std::vector<float> normals;
};

/// The drawn tissue of `def` over `triangles` (the scene's tissue triangles), smooth when
/// def.surface asks for it (and the smooth surface can be built; else the triangles as they are).
TissueSurface tissueSurface(const sim::SceneDef& def, const std::vector<std::array<int, 3>>& triangles);

/// Each vertex of `surface` where `snapshot` puts it, with its normal, into `mesh` (its vertices
/// only; the indices are surface.indices): at its node and with the node's normal, or on the
/// smooth surface through the snapshot's nodes.
void placeTissue(TissueSurface& surface, const sim::RenderSnapshot& snapshot, ShadedMesh& mesh);

}  // namespace microsim::gui
