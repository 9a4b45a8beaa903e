#include "gui/render/draw_list.h"

#include <QQuaternion>

#include <algorithm>
#include <iterator>

namespace microsim::gui {

namespace {

const Material kDrapeMaterial{{0.08f, 0.26f, 0.28f}, 0.05f, 8.0f};
const Material kVesselMaterial{kVesselOuter, 0.35f, 48.0f};
// microforceps and scissor shafts have a non-glare finish (dark titanium), as real ones do so
// that they do not dazzle under the microscope's light; the polished needle is the one bright
// metal in the field, which is how the eye finds it
const Material kJawMaterial{{0.18f, 0.19f, 0.21f}, 0.06f, 10.0f};
const Material kBladeMaterial{{0.72f, 0.74f, 0.78f}, 0.9f, 96.0f};
const Material kNeedleMaterial{{0.80f, 0.80f, 0.84f}, 0.9f, 80.0f};
// a deep saturated blue: darker than the drape and the wall, so the thread reads against both
const Material kThreadMaterial{{0.02f, 0.05f, 0.60f}, 0.35f, 40.0f};
const QVector3D kGuideColour(0.15f, 0.95f, 0.35f);
const QVector3D kGuideDoneColour(0.45f, 0.50f, 0.47f);

// sizes of the marks as fractions of the camera's field (its height at the target, mm): a
// constant size on screen however far the microscope is zoomed
constexpr float kTipRadius = 0.008f;
constexpr float kCueRadius = 0.014f;
constexpr float kGuideLine = 0.002f;
constexpr float kGuideLineFloor = 0.012f;  // mm: never thinner than this

QVector3D listVector(const Eigen::Vector3d& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}

DrawItem sceneItem(DrawKind kind, DrawMesh mesh, const Material& material, bool castsShadow) {
  DrawItem item;
  item.kind = kind;
  item.mesh = mesh;
  item.material = material;
  item.castsShadow = castsShadow;
  return item;
}

// a mark drawn on top: `mesh` at `at`, turned by `turn`, scaled by `scale`
DrawItem markItem(DrawKind kind, DrawMesh mesh, int hand, const QVector3D& at, const QQuaternion& turn,
                  const QVector3D& scale, const QVector3D& colour) {
  DrawItem item = sceneItem(kind, mesh, {colour, 0.2f, 16.0f}, false);
  item.hand = hand;
  item.onTop = true;
  item.model.translate(at);
  item.model.rotate(turn);
  item.model.scale(scale);
  return item;
}

QVector3D tipColour(const sim::ToolSnapshot& tool) {
  if (tool.holdsTissue || tool.holdsSuture) return kTipHolding;
  if (tool.between != sim::JawTarget::Nothing) return kTipContact;
  return kTipIdle;
}

void appendGuides(const std::vector<Guide>& guides, float field, DrawList& list) {
  const float line = std::max(kGuideLineFloor, kGuideLine * field);
  for (const Guide& g : guides) {
    const QVector3D at = listVector(g.point);
    const QQuaternion turn = QQuaternion::rotationTo({0.0f, 0.0f, 1.0f}, listVector(g.direction).normalized());
    const auto size = static_cast<float>(g.size);
    const QVector3D colour = g.done ? kGuideDoneColour : kGuideColour;
    if (g.kind == Guide::Kind::Target)
      list.push_back(markItem(DrawKind::Guide, DrawMesh::Ring, -1, at, turn, {size, size, size}, colour));
    else
      list.push_back(markItem(DrawKind::Guide, DrawMesh::Arrow, -1, at, turn, {line, line, size}, colour));
  }
}

// the hand holds its forceps: the scene has one for it and the hand has not taken up another tool
bool holdsForceps(const sim::SceneDef& def, const sim::RenderSnapshot& snapshot, int hand) {
  const auto hs = static_cast<std::size_t>(hand);
  return snapshot.forceps[hs].present && def.forceps[hs] && !snapshot.scalpels[hs].present &&
         !snapshot.scissors[hs].present;
}

}  // namespace

DrawMesh jawMeshOf(sim::Hand hand) { return hand == sim::Hand::Left ? DrawMesh::LeftJaw : DrawMesh::RightJaw; }

QMatrix4x4 toQMatrix(const Eigen::Matrix4f& m) {
  return QMatrix4x4(m.data()).transposed();  // Eigen is column-major, QMatrix4x4(const float*) row-major
}

DrawList buildDrawList(const sim::SceneDef& def, const sim::RenderSnapshot& snapshot,
                       const MicroscopeCamera& camera, const std::vector<Guide>& guides) {
  DrawList list;

  // the drape and the tissue, in the scene frame; the tissue's vertex colours tell the lumen
  list.push_back(sceneItem(DrawKind::Background, DrawMesh::Background, kDrapeMaterial, false));
  list.push_back(sceneItem(DrawKind::Tissue, DrawMesh::Tissue, kVesselMaterial, true));

  // the tools in the hands: a hand holding the scalpel or the scissors has put its forceps down
  for (int h = 0; h < sim::kHandCount; ++h) {
    const auto hs = static_cast<std::size_t>(h);
    const sim::ToolSnapshot& forceps = snapshot.forceps[hs];
    if (holdsForceps(def, snapshot, h)) {
      for (const Eigen::Matrix4f& jaw : forceps.jaws) {
        DrawItem item = sceneItem(DrawKind::ForcepsJaw, jawMeshOf(static_cast<sim::Hand>(h)), kJawMaterial, true);
        item.hand = h;
        item.model = toQMatrix(jaw);
        list.push_back(item);
      }
    }
    if (snapshot.scalpels[hs].present && def.scalpel) {
      DrawItem item = sceneItem(DrawKind::Scalpel, DrawMesh::ScalpelBlade, kBladeMaterial, true);
      item.hand = h;
      item.model = toQMatrix(snapshot.scalpels[hs].pose);
      list.push_back(item);
    }
    const sim::ScissorsSnapshot& scissors = snapshot.scissors[hs];
    if (scissors.present && def.scissors) {
      for (const Eigen::Matrix4f& blade : scissors.blades) {
        DrawItem item = sceneItem(DrawKind::Scissors, DrawMesh::ScissorsBlade, kBladeMaterial, true);
        item.hand = h;
        item.model = toQMatrix(blade);
        list.push_back(item);
      }
      DrawItem shaft = sceneItem(DrawKind::Scissors, DrawMesh::ScissorsShaft, kJawMaterial, true);
      shaft.hand = h;
      shaft.model = toQMatrix(scissors.pose);
      list.push_back(shaft);
    }
  }

  // the needle up to the swage, the thread from it (tubes built from the snapshot's nodes)
  const int sutureNodes = static_cast<int>(snapshot.suturePositions.size() / 3);
  if (sutureNodes > 1) {
    const int lastNeedle = std::clamp(snapshot.needleNodes - 1, 0, sutureNodes - 1);
    if (lastNeedle > 0) list.push_back(sceneItem(DrawKind::Needle, DrawMesh::Needle, kNeedleMaterial, true));
    if (sutureNodes - 1 > lastNeedle) list.push_back(sceneItem(DrawKind::Thread, DrawMesh::Thread, kThreadMaterial, true));
  }

  // marks on top: where each forceps' jaws meet, and a ring around what they would take
  const float field = camera.mmPerPixel(1);
  // rings face halfway between the microscope and the side view (side_view.h), which looks
  // along the microscope's up axis: a ring, open in the middle, in both
  const QVector3D normal = (-camera.forward() - camera.up()).normalized();
  const QQuaternion facing =
      QQuaternion::fromAxes(camera.right(), QVector3D::crossProduct(normal, camera.right()), normal);
  for (int h = 0; h < sim::kHandCount; ++h) {
    const auto hs = static_cast<std::size_t>(h);
    const sim::ToolSnapshot& forceps = snapshot.forceps[hs];
    if (!holdsForceps(def, snapshot, h)) continue;
    const QVector3D tip(forceps.pose(0, 3), forceps.pose(1, 3), forceps.pose(2, 3));
    const float r = kTipRadius * field;
    list.push_back(markItem(DrawKind::TipMarker, DrawMesh::Reticle, h, tip, facing, {r, r, r}, tipColour(forceps)));
    if (forceps.between != sim::JawTarget::Nothing && !forceps.holdsTissue && !forceps.holdsSuture) {
      const QVector3D at(forceps.betweenPoint.x(), forceps.betweenPoint.y(), forceps.betweenPoint.z());
      const float ring = kCueRadius * field;
      list.push_back(markItem(DrawKind::ContactCue, DrawMesh::Ring, h, at, facing, {ring, ring, ring}, kTipContact));
    }
  }
  appendGuides(guides, field, list);
  return list;
}

std::vector<float> tissueVertexColours(const sim::SceneDef& def) {
  const auto& triangles = def.tissue.model.triangles();
  std::vector<float> colours(static_cast<std::size_t>(def.tissue.model.nodeCount()) * 3);
  const auto paint = [&](int vertex, const QVector3D& c) {
    const auto k = 3 * static_cast<std::size_t>(vertex);
    colours[k] = c.x();
    colours[k + 1] = c.y();
    colours[k + 2] = c.z();
  };
  for (int i = 0; i < def.tissue.model.nodeCount(); ++i) paint(i, kVesselOuter);
  for (const sim::SceneVessel& v : def.vessels)
    for (int t = v.innerSurface.begin; t < v.innerSurface.end; ++t)
      for (int i : triangles[static_cast<std::size_t>(t)]) paint(i, kVesselLumen);
  return colours;
}

DrawList placeholderDrawList() {
  return {sceneItem(DrawKind::Placeholder, DrawMesh::Placeholder, kVesselMaterial, false)};
}

DrawList shadowCasters(const DrawList& list) {
  DrawList casters;
  std::copy_if(list.begin(), list.end(), std::back_inserter(casters), [](const DrawItem& i) { return i.castsShadow; });
  return casters;
}

}  // namespace microsim::gui
