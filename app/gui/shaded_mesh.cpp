#include "gui/shaded_mesh.h"

#include "microsim/sim/scene/render_snapshot.h"

#include <cmath>
#include <numbers>

namespace microsim::gui {

namespace {

void addVertex(ShadedMesh& mesh, float x, float y, float z, float nx, float ny, float nz) {
  mesh.vertices.push_back({{x, y, z}, {nx, ny, nz}});
}

// a cylinder wall of `radius` along x; normals point outward (sign +1) or inward (-1)
void addWall(ShadedMesh& mesh, float radius, float length, int around, int along, float sign) {
  const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
  for (int j = 0; j <= along; ++j) {
    const float x = -0.5f * length + length * static_cast<float>(j) / static_cast<float>(along);
    // a gentle bulge so the shading shows curvature along the vessel too
    const float r = radius * (1.0f + 0.08f * std::sin(std::numbers::pi_v<float> * static_cast<float>(j) / static_cast<float>(along)));
    for (int i = 0; i <= around; ++i) {
      const float a = 2.0f * std::numbers::pi_v<float> * static_cast<float>(i) / static_cast<float>(around);
      const float c = std::cos(a);
      const float s = std::sin(a);
      addVertex(mesh, x, r * c, r * s, 0.0f, sign * c, sign * s);
    }
  }
  const auto row = static_cast<std::uint32_t>(around + 1);
  for (int j = 0; j < along; ++j) {
    for (int i = 0; i < around; ++i) {
      const std::uint32_t a = first + static_cast<std::uint32_t>(j) * row + static_cast<std::uint32_t>(i);
      const std::uint32_t b = a + row;
      if (sign > 0) {
        mesh.indices.insert(mesh.indices.end(), {a, a + 1, b, b, a + 1, b + 1});
      } else {
        mesh.indices.insert(mesh.indices.end(), {a, b, a + 1, b, b + 1, a + 1});
      }
    }
  }
}

// the ring between the inner and outer wall at one end, facing along ±x
void addAnnulus(ShadedMesh& mesh, float inner, float outer, float x, int around, float facing) {
  const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
  for (int i = 0; i <= around; ++i) {
    const float a = 2.0f * std::numbers::pi_v<float> * static_cast<float>(i) / static_cast<float>(around);
    addVertex(mesh, x, inner * std::cos(a), inner * std::sin(a), facing, 0.0f, 0.0f);
    addVertex(mesh, x, outer * std::cos(a), outer * std::sin(a), facing, 0.0f, 0.0f);
  }
  for (int i = 0; i < around; ++i) {
    const std::uint32_t a = first + 2u * static_cast<std::uint32_t>(i);
    if (facing > 0) {
      mesh.indices.insert(mesh.indices.end(), {a, a + 1, a + 2, a + 2, a + 1, a + 3});
    } else {
      mesh.indices.insert(mesh.indices.end(), {a, a + 2, a + 1, a + 2, a + 3, a + 1});
    }
  }
}

}  // namespace

ShadedMesh makeVesselPlaceholder(int segmentsAround, int segmentsAlong) {
  constexpr float kRadius = 0.5f;
  constexpr float kWall = 0.1f;
  constexpr float kLength = 4.0f;
  ShadedMesh mesh;
  addWall(mesh, kRadius, kLength, segmentsAround, segmentsAlong, +1.0f);
  addWall(mesh, kRadius - kWall, kLength, segmentsAround, segmentsAlong, -1.0f);
  addAnnulus(mesh, kRadius - kWall, kRadius, 0.5f * kLength, segmentsAround, +1.0f);
  addAnnulus(mesh, kRadius - kWall, kRadius, -0.5f * kLength, segmentsAround, -1.0f);
  return mesh;
}

ShadedMesh meshFromTriangles(const std::vector<float>& xyz, const std::vector<std::array<int, 3>>& triangles) {
  std::vector<float> normals;
  sim::vertexNormals(xyz, triangles, normals);
  ShadedMesh mesh;
  mesh.vertices.resize(xyz.size() / 3);
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    for (std::size_t r = 0; r < 3; ++r) {
      mesh.vertices[i].position[r] = xyz[3 * i + r];
      mesh.vertices[i].normal[r] = normals[3 * i + r];
    }
  mesh.indices.reserve(triangles.size() * 3);
  for (const auto& t : triangles)
    for (int i : t) mesh.indices.push_back(static_cast<std::uint32_t>(i));
  return mesh;
}

}  // namespace microsim::gui
