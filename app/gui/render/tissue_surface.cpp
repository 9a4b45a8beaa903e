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

// the copy of drawn point `point` that one end face uses (`copies`: that face's so far), made on
// first use
std::uint32_t endFaceVertex(TissueSurface& s, std::unordered_map<int, std::uint32_t>& copies,
                            int point) {
  const auto found = copies.find(point);
  if (found != copies.end()) return found->second;
  const auto copy = static_cast<std::uint32_t>(s.source.size());
  s.source.push_back(point);
  s.colours.insert(s.colours.end(), {kVesselCutFace.x(), kVesselCutFace.y(), kVesselCutFace.z()});
  const auto from = 4 * static_cast<std::size_t>(point);
  s.surface.insert(s.surface.end(), {s.surface[from], s.surface[from + 1], s.surface[from + 2],
                                     static_cast<float>(TissueLayer::CutFace)});
  copies.emplace(point, copy);
  return copy;
}

// What is drawn before the end faces get their copies: the nodes over the scene's triangles,
// or the smooth surface's vertices over its refined ones; each drawn triangle knows the scene
// triangle it lies in.
struct DrawnPoints {
  sim::Points rest;
  std::vector<float> colours;  // 3 per point
  const std::vector<std::array<int, 3>>* triangles = nullptr;
  std::vector<int> parent;  // per drawn triangle, empty: the scene's own
  int sceneTriangle(std::size_t t) const {
    return parent.empty() ? static_cast<int>(t) : parent[t];
  }
};

DrawnPoints drawnPoints(const sim::SceneDef& def, const std::vector<std::array<int, 3>>& triangles,
                        const sim::SmoothSurface* smooth) {
  DrawnPoints d;
  if (!smooth) {
    d.rest = def.tissue.model.restPositions();
    d.colours = tissueVertexColours(def);
    d.triangles = &triangles;
    return d;
  }
  smooth->place(def.tissue.model.restPositions(), d.rest);
  smooth->blend(tissueVertexColours(def), 3, d.colours);
  d.triangles = &smooth->triangles();
  d.parent = smooth->parentTriangles();
  return d;
}

}  // namespace

TissueSurface tissueSurface(const sim::SceneDef& def, const std::vector<std::array<int, 3>>& triangles) {
  TissueSurface s;
  if (def.surface.subdivision > 0)
    if (auto smooth = sim::SmoothSurface::build(triangles, def.tissue.model.restPositions(),
                                                def.surface.subdivision))
      s.smooth = std::make_shared<const sim::SmoothSurface>(std::move(*smooth));
  const DrawnPoints drawn = drawnPoints(def, triangles, s.smooth.get());
  const auto& drawnTriangles = *drawn.triangles;
  const auto points = static_cast<int>(drawn.rest.cols());
  s.source.resize(static_cast<std::size_t>(points));
  for (int i = 0; i < points; ++i) s.source[static_cast<std::size_t>(i)] = i;
  s.colours = drawn.colours;
  s.surface.resize(4 * static_cast<std::size_t>(points));
  for (int i = 0; i < points; ++i)
    setSurfacePoint(s, static_cast<std::size_t>(i), drawn.rest.col(i), TissueLayer::OuterWall);

  // each vessel's points in its own frame; the lumen darker the deeper it lies from an end
  std::vector<bool> endFace(drawnTriangles.size(), false);
  for (const sim::SceneVessel& v : def.vessels) {
    const VesselFrame frame(v.def);
    const double inner = v.def.radius - v.def.wallThickness;
    const auto in = [](const sim::TriangleRange& r, int sceneTriangle) {
      return sceneTriangle >= r.begin && sceneTriangle < r.end;
    };
    const auto inVessel = [&](int sceneTriangle) {
      return in(v.outerSurface, sceneTriangle) || in(v.innerSurface, sceneTriangle) ||
             in(v.clampedEnd, sceneTriangle) || in(v.cutEnd, sceneTriangle);
    };
    std::vector<bool> lumenDone(static_cast<std::size_t>(points), false);
    for (std::size_t t = 0; t < drawnTriangles.size(); ++t) {
      const int sceneTriangle = drawn.sceneTriangle(t);
      if (!inVessel(sceneTriangle)) continue;
      for (int i : drawnTriangles[t])
        setSurfacePoint(s, static_cast<std::size_t>(i), frame.local(drawn.rest.col(i)),
                        TissueLayer::OuterWall);
    }
    for (std::size_t t = 0; t < drawnTriangles.size(); ++t) {
      if (!in(v.innerSurface, drawn.sceneTriangle(t))) continue;
      for (int i : drawnTriangles[t]) {
        const auto k = static_cast<std::size_t>(i);
        if (lumenDone[k]) continue;
        lumenDone[k] = true;
        s.surface[4 * k + 3] = static_cast<float>(TissueLayer::Lumen);
        // occlusion: one lumen diameter in from the nearer end keeps about a third of the light
        const double along = frame.local(drawn.rest.col(i)).x();
        const double depth = std::max(0.0, std::min(along, v.def.length - along));
        const auto open = static_cast<float>(std::exp(-depth / std::max(1e-6, 2.0 * inner)));
        scaleColour(s, k, kLumenDeepest + (1.0f - kLumenDeepest) * open);
      }
    }
    // the end annuli draw copies of their points, in the cut face's colour
    for (const sim::TriangleRange& part : {v.clampedEnd, v.cutEnd}) {
      std::unordered_map<int, std::uint32_t> copies;
      for (std::size_t t = 0; t < drawnTriangles.size(); ++t) {
        if (!in(part, drawn.sceneTriangle(t))) continue;
        endFace[t] = true;
        for (int i : drawnTriangles[t]) s.indices.push_back(endFaceVertex(s, copies, i));
      }
    }
  }
  for (std::size_t t = 0; t < drawnTriangles.size(); ++t)
    if (!endFace[t])
      for (int i : drawnTriangles[t]) s.indices.push_back(static_cast<std::uint32_t>(i));
  if (s.smooth) {
    s.triangles.resize(s.indices.size() / 3);
    for (std::size_t t = 0; t < s.triangles.size(); ++t)
      for (std::size_t k = 0; k < 3; ++k)
        s.triangles[t][k] = static_cast<int>(s.indices[3 * t + k]);
  }
  return s;
}

void placeTissue(TissueSurface& surface, const sim::RenderSnapshot& snapshot, ShadedMesh& mesh) {
  const std::size_t nodes = snapshot.tissuePositions.size() / 3;
  mesh.vertices.resize(surface.source.size());
  if (surface.smooth) {
    if (nodes < surface.smooth->nodeVertices().size())
      return;  // a snapshot of another scene: left where it was
    surface.smooth->place(snapshot.tissuePositions.data(), surface.refined);
    surface.positions.resize(3 * surface.source.size());
    for (std::size_t v = 0; v < surface.source.size(); ++v)
      for (std::size_t r = 0; r < 3; ++r)
        surface.positions[3 * v + r] =
            surface.refined[3 * static_cast<std::size_t>(surface.source[v]) + r];
    // the end faces' copies have triangles of their own: their normals stay the face's, the rims
    // crisp
    sim::vertexNormals(surface.positions, surface.triangles, surface.normals);
    for (std::size_t v = 0; v < surface.source.size(); ++v)
      for (std::size_t r = 0; r < 3; ++r) {
        mesh.vertices[v].position[r] = surface.positions[3 * v + r];
        mesh.vertices[v].normal[r] = surface.normals[3 * v + r];
      }
    return;
  }
  for (std::size_t v = 0; v < surface.source.size(); ++v) {
    const auto n = static_cast<std::size_t>(surface.source[v]);
    if (n >= nodes) continue;  // a snapshot of another scene: left where it was
    for (std::size_t r = 0; r < 3; ++r) {
      mesh.vertices[v].position[r] = snapshot.tissuePositions[3 * n + r];
      mesh.vertices[v].normal[r] = snapshot.tissueNormals[3 * n + r];
    }
  }
}

}  // namespace microsim::gui
