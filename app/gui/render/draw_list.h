#pragma once
// Visualise, then render (MuJoCo's mjv_updateScene → mjr_render; STYLE.md 17): a pure function
// turns the scene's static definition, one RenderSnapshot, the camera and the Learn-mode
// guides into the list of things to draw, in drawing order; the viewport only draws the list.
// Every pass reuses it: the lit pass draws every item, the shadow pass the items that cast a
// shadow (shadowCasters), the side view (side_view.h) the same list from another camera, and
// a stereo pair the same list once per eye. Nothing here touches GL, so the list is tested
// without a context (tests/app/gui/render/draw_list_test.cpp).
//
// An item names a mesh the viewport holds (DrawMesh: the tissue and the suture's tubes built
// from the snapshot, the tools' meshes read from the scene, unit markers) and places it with
// a model transform (mesh frame → scene), a material and three flags. What the snapshot says
// the tools do shows as items too: each forceps' tip marker, where its jaws meet, coloured by
// what the jaws would close on now (the engine's answer, ToolSnapshot::between) or hold (a
// reticle: what lies exactly at the tip stays visible), and a contact ring around the point
// they would take.
//
// Units: millimetres; colours linear RGB.

#include "gui/render/camera.h"
#include "gui/render/guide.h"

#include "microsim/sim/scene/render_snapshot.h"
#include "microsim/sim/scene/scene_def.h"

#include <QMatrix4x4>
#include <QVector3D>

#include <cstdint>
#include <vector>

namespace microsim::gui {

/// What an item shows.
enum class DrawKind : std::uint8_t {
  Placeholder,  ///< the vessel drawn while no scene runs
  Background,   ///< the plane behind the tissue; the shadows fall on it
  Tissue,
  Needle,
  Thread,
  ForcepsJaw,
  Scalpel,
  Scissors,     ///< a hand's microscissors: two blades and the shaft
  TipMarker,    ///< where a forceps' jaws meet: a reticle, its centre open
  ContactCue,   ///< a ring around what a forceps' jaws would take if they closed now
  Guide,        ///< a Learn-mode mark (guide.h)
};

/// The meshes the viewport holds, one GPU buffer each.
enum class DrawMesh : std::uint8_t {
  Placeholder,  ///< makeVesselPlaceholder(), scene frame
  Background,   ///< background_plane.h, scene frame
  Tissue,       ///< the snapshot's tissue with the scene's triangles, scene frame
  Needle,       ///< a tube over the snapshot's needle nodes, scene frame
  Thread,       ///< a tube over the snapshot's thread nodes, scene frame
  LeftJaw,      ///< the left forceps' jaw mesh, jaw frame (tool_meshes.h)
  RightJaw,     ///< the right forceps' jaw mesh, jaw frame
  ScalpelBlade, ///< the scalpel, blade frame (tool_meshes.h)
  ScissorsBlade, ///< one scissors blade, blade frame (tool_meshes.h)
  ScissorsShaft, ///< the scissors' shaft behind the pivot, tool frame
  Ring,         ///< unit circle in the xy plane, a tube of radius kRingTube (marker_meshes.h)
  Reticle,      ///< unit circle in the xy plane, a tube of radius kReticleTube
  Arrow,        ///< unit arrow from the origin along +z, shaft radius 1 (marker_meshes.h)
};
inline constexpr int kDrawMeshCount = 13;

/// The jaw mesh of a hand's forceps.
DrawMesh jawMeshOf(sim::Hand hand);

struct Material {
  QVector3D colour;        ///< linear RGB
  float specular = 0.3f;   ///< strength of the highlight
  float shininess = 32.0f; ///< Phong exponent
};

struct DrawItem {
  DrawKind kind = DrawKind::Tissue;
  DrawMesh mesh = DrawMesh::Tissue;
  int hand = -1;  ///< the hand whose tool this is (0 left, 1 right), -1 for none
  QMatrix4x4 model;  ///< mesh frame → scene
  Material material;  ///< the tissue's mesh carries its own colours (outer wall, lumen)
  bool castsShadow = false;    ///< drawn by the shadow pass onto the background
  bool onTop = false;          ///< drawn over everything (no depth test): marks, not matter
};

using DrawList = std::vector<DrawItem>;

/// The items of one frame, in drawing order: the background, the tissue, each forceps' jaws
/// (not while its hand holds the scalpel or the scissors: the forceps is put down), each
/// scalpel in a hand, the scissors in a hand (both blades at the engine's pose and opening,
/// then the shaft),
/// the needle and the thread, then the marks drawn on top: tip markers, contact rings and
/// guides. Marks are sized to the camera's field (a constant size on screen at the target).
DrawList buildDrawList(const sim::SceneDef& def, const sim::RenderSnapshot& snapshot,
                       const MicroscopeCamera& camera, const std::vector<Guide>& guides);

/// What is drawn while no scene runs: the placeholder vessel.
DrawList placeholderDrawList();

/// The items of `list` that cast a shadow, in its order.
DrawList shadowCasters(const DrawList& list);

/// QMatrix4x4 from an Eigen (column-major) 4×4 matrix.
QMatrix4x4 toQMatrix(const Eigen::Matrix4f& m);

/// The tissue's colours per vertex (3 floats each, linear RGB, in the scene's node order):
/// the vessels' inner wall (lumen) darker than the outer wall and the rest of the tissue.
std::vector<float> tissueVertexColours(const sim::SceneDef& def);

/// The tissue's colours: the outer wall, the lumen.
inline const QVector3D kVesselOuter(0.78f, 0.26f, 0.24f);
inline const QVector3D kVesselLumen(0.50f, 0.07f, 0.12f);

/// Tip marker colours: idle, the jaws would close on something, the jaws hold something.
inline const QVector3D kTipIdle(0.85f, 0.85f, 0.80f);
inline const QVector3D kTipContact(1.0f, 0.80f, 0.05f);
inline const QVector3D kTipHolding(0.05f, 0.85f, 0.95f);

}  // namespace microsim::gui
