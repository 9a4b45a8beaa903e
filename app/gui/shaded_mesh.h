#pragma once
// A triangle mesh ready for the GPU: interleaved position (mm) and unit normal, and
// counter-clockwise triangles.

#include <array>
#include <cstdint>
#include <vector>

namespace microsim::gui {

struct ShadedVertex {
  float position[3];
  float normal[3];
};

struct ShadedMesh {
  std::vector<ShadedVertex> vertices;
  std::vector<std::uint32_t> indices;  ///< three per triangle
};

/// A short straight vessel segment (outer wall, lumen and end annuli), the viewport's
/// placeholder until a lesson's scene is loaded. Radius 0.5 mm, wall 0.1 mm, length 4 mm,
/// along x.
ShadedMesh makeVesselPlaceholder(int segmentsAround = 48, int segmentsAlong = 24);

/// A mesh from positions (3 floats per vertex, mm) and triangles, with area-weighted vertex
/// normals (sim::vertexNormals): the forceps jaw and other static meshes of a scene.
ShadedMesh meshFromTriangles(const std::vector<float>& xyz, const std::vector<std::array<int, 3>>& triangles);

}  // namespace microsim::gui
