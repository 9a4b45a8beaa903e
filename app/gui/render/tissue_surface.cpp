#include "gui/render/tissue_surface.h"

#include "gui/render/draw_list.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace microsim::gui {

namespace {

// a vessel's own frame: its axis from the clamped end, and two directions across it (mesh/vessel.h)
struct VesselFrame {
  sim::Vec3 origin;
  sim::Vec3 axis;
  sim::Vec3 across;
  sim::Vec3 across2;

  explicit VesselFrame(const sim::VesselDef& def) : origin(def.origin), axis(def.direction.normalized()) {
    const sim::Vec3 reference = std::abs(axis.z()) > 0.9 ? sim::Vec3::UnitX() : sim::Vec3::UnitZ();
    across = (reference - reference.dot(axis) * axis).normalized();
    across2 = axis.cross(across);
  }
  sim::Vec3 local(const sim::Vec3& x) const {
    const sim::Vec3 d = x - origin;
    return {d.dot(axis), d.dot(across), d.dot(across2)};
  }
};

void setSurfacePoint(TissueSurface& s, std::size_t vertex, const sim::Vec3& point, TissueLayer layer) {
  float* out = &s.surface[4 * vertex];
  out[0] = static_cast<float>(point.x());
  out[1] = static_cast<float>(point.y());
  out[2] = static_cast<float>(point.z());
  out[3] = static_cast<float>(layer);
}

void scaleColour(TissueSurface& s, std::size_t vertex, float keep) {
  for (std::size_t c = 0; c < 3; ++c) s.colours[3 * vertex + c] *= keep;
}

// the copy of `node` that one end face uses (`copies`: that face's so far), made on first use
std::uint32_t endFaceVertex(TissueSurface& s, std::unordered_map<int, std::uint32_t>& copies, int node) {
  const auto found = copies.find(node);
  if (found != copies.end()) return found->second;
  const auto copy = static_cast<std::uint32_t>(s.node.size());
  s.node.push_back(node);
  s.colours.insert(s.colours.end(), {kVesselCutFace.x(), kVesselCutFace.y(), kVesselCutFace.z()});
  const auto from = 4 * static_cast<std::size_t>(node);
  s.surface.insert(s.surface.end(), {s.surface[from], s.surface[from + 1], s.surface[from + 2],
                                     static_cast<float>(TissueLayer::CutFace)});
  copies.emplace(node, copy);
  return copy;
}

}  // namespace

TissueSurface tissueSurface(const sim::SceneDef& def, const std::vector<std::array<int, 3>>& triangles) {
  TissueSurface s;
  const int nodes = def.tissue.model.nodeCount();
  const auto rest = def.tissue.model.restPositions();
  s.node.resize(static_cast<std::size_t>(nodes));
  for (int i = 0; i < nodes; ++i) s.node[static_cast<std::size_t>(i)] = i;
  s.colours = tissueVertexColours(def);
  s.surface.resize(4 * static_cast<std::size_t>(nodes));
  for (int i = 0; i < nodes; ++i)
    setSurfacePoint(s, static_cast<std::size_t>(i), rest.col(i), TissueLayer::OuterWall);

  // each vessel's nodes in its own frame; the lumen darker the deeper it lies from an end
  std::vector<bool> endFace(triangles.size(), false);
  for (const sim::SceneVessel& v : def.vessels) {
    const VesselFrame frame(v.def);
    const double inner = v.def.radius - v.def.wallThickness;
    const auto inRange = [&triangles](const sim::TriangleRange& r) {
      return std::pair{std::clamp(r.begin, 0, static_cast<int>(triangles.size())),
                       std::clamp(r.end, 0, static_cast<int>(triangles.size()))};
    };
    for (const sim::TriangleRange& part : {v.outerSurface, v.innerSurface, v.clampedEnd, v.cutEnd}) {
      const auto [begin, end] = inRange(part);
      for (int t = begin; t < end; ++t)
        for (int i : triangles[static_cast<std::size_t>(t)])
          setSurfacePoint(s, static_cast<std::size_t>(i), frame.local(rest.col(i)), TissueLayer::OuterWall);
    }
    std::vector<bool> lumenDone(static_cast<std::size_t>(nodes), false);
    const auto [innerBegin, innerEnd] = inRange(v.innerSurface);
    for (int t = innerBegin; t < innerEnd; ++t)
      for (int i : triangles[static_cast<std::size_t>(t)]) {
        const auto k = static_cast<std::size_t>(i);
        if (lumenDone[k]) continue;
        lumenDone[k] = true;
        s.surface[4 * k + 3] = static_cast<float>(TissueLayer::Lumen);
        // occlusion: one lumen diameter in from the nearer end keeps about a third of the light
        const double along = frame.local(rest.col(i)).x();
        const double depth = std::max(0.0, std::min(along, v.def.length - along));
        const auto open = static_cast<float>(std::exp(-depth / std::max(1e-6, 2.0 * inner)));
        scaleColour(s, k, kLumenDeepest + (1.0f - kLumenDeepest) * open);
      }
    // the end annuli draw copies of their nodes, in the cut face's colour
    for (const sim::TriangleRange& part : {v.clampedEnd, v.cutEnd}) {
      std::unordered_map<int, std::uint32_t> copies;
      const auto [begin, end] = inRange(part);
      for (int t = begin; t < end; ++t) {
        endFace[static_cast<std::size_t>(t)] = true;
        for (int i : triangles[static_cast<std::size_t>(t)]) s.indices.push_back(endFaceVertex(s, copies, i));
      }
    }
  }
  for (std::size_t t = 0; t < triangles.size(); ++t)
    if (!endFace[t])
      for (int i : triangles[t]) s.indices.push_back(static_cast<std::uint32_t>(i));
  return s;
}

void placeTissue(const TissueSurface& surface, const sim::RenderSnapshot& snapshot, ShadedMesh& mesh) {
  const std::size_t nodes = snapshot.tissuePositions.size() / 3;
  mesh.vertices.resize(surface.node.size());
  for (std::size_t v = 0; v < surface.node.size(); ++v) {
    const auto n = static_cast<std::size_t>(surface.node[v]);
    if (n >= nodes) continue;  // a snapshot of another scene: left where it was
    for (std::size_t r = 0; r < 3; ++r) {
      mesh.vertices[v].position[r] = snapshot.tissuePositions[3 * n + r];
      mesh.vertices[v].normal[r] = snapshot.tissueNormals[3 * n + r];
    }
  }
}

}  // namespace microsim::gui
