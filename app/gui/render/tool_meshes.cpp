#include "gui/render/tool_meshes.h"

#include "gui/render/tube_builder.h"

#include <array>
#include <cstdint>
#include <vector>

namespace microsim::gui {

namespace {

// an axis-aligned box from `low` to `high`, each face with its own normal
void appendToolBox(const std::array<float, 3>& low, const std::array<float, 3>& high, ShadedMesh& mesh) {
  for (int axis = 0; axis < 3; ++axis) {
    for (const int side : {-1, 1}) {
      const int u = (axis + 1) % 3;
      const int v = (axis + 2) % 3;
      const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
      constexpr std::array<std::array<int, 2>, 4> kCorners{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
      for (const auto& [su, sv] : kCorners) {
        ShadedVertex vertex{};
        vertex.position[axis] = side < 0 ? low[static_cast<std::size_t>(axis)] : high[static_cast<std::size_t>(axis)];
        vertex.position[u] = su == 0 ? low[static_cast<std::size_t>(u)] : high[static_cast<std::size_t>(u)];
        vertex.position[v] = sv == 0 ? low[static_cast<std::size_t>(v)] : high[static_cast<std::size_t>(v)];
        vertex.normal[axis] = static_cast<float>(side);
        mesh.vertices.push_back(vertex);
      }
      // counter-clockwise seen from outside: (u, v, axis) is right-handed
      if (side > 0) mesh.indices.insert(mesh.indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
      else mesh.indices.insert(mesh.indices.end(), {first, first + 2, first + 1, first, first + 3, first + 2});
    }
  }
}

}  // namespace

ShadedMesh jawMesh(const sim::ForcepsDef& def) {
  std::vector<float> xyz(static_cast<std::size_t>(def.jawVertices.cols()) * 3);
  for (Eigen::Index i = 0; i < def.jawVertices.cols(); ++i)
    for (int r = 0; r < 3; ++r) xyz[static_cast<std::size_t>(3 * i + r)] = static_cast<float>(def.jawVertices(r, i));
  return meshFromTriangles(xyz, def.jawTriangles);
}

ShadedMesh scalpelMesh(const sim::ScalpelDef& def) {
  const auto length = static_cast<float>(def.bladeLength);
  const auto height = static_cast<float>(def.bladeHeight);
  ShadedMesh mesh;
  appendToolBox({0.0f, -0.5f * kBladeThickness, 0.0f}, {length, 0.5f * kBladeThickness, height}, mesh);
  const float middle = 0.5f * height;
  const std::vector<float> handle{length, 0.0f, middle, length + kScalpelHandleLength, 0.0f, middle};
  appendTube(handle, 0, 1, {}, TubeStyle{kScalpelHandleRadius, 10, 1}, mesh);
  return mesh;
}

ShadedMesh scissorsBladeMesh(const sim::ScissorsDef& def) {
  const auto length = static_cast<float>(def.bladeLength);
  const auto half = static_cast<float>(def.bladeHalfThickness);
  ShadedMesh mesh;
  appendToolBox({0.0f, 0.0f, -half}, {length, kScissorsBladeWidth, half}, mesh);
  return mesh;
}

ShadedMesh scissorsShaftMesh(const sim::ScissorsDef& def) {
  const auto pivot = static_cast<float>(def.bladeLength);
  ShadedMesh mesh;
  const std::vector<float> shaft{pivot, 0.0f, 0.0f, pivot + kScissorsShaftLength, 0.0f, 0.0f};
  appendTube(shaft, 0, 1, {}, TubeStyle{kScissorsShaftRadius, 10, 1}, mesh);
  return mesh;
}

}  // namespace microsim::gui
