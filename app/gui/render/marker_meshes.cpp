#include "gui/render/marker_meshes.h"

#include "gui/render/tube_builder.h"

#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

namespace microsim::gui {

namespace {

constexpr float kArrowShaftEnd = 0.7f;
constexpr float kArrowConeRadius = 3.0f;

float markerTurn(int k, int of) {
  return 2.0f * std::numbers::pi_v<float> * static_cast<float>(k) / static_cast<float>(of);
}

void pushMarkerVertex(ShadedMesh& mesh, float x, float y, float z, float nx, float ny, float nz) {
  mesh.vertices.push_back({{x, y, z}, {nx, ny, nz}});
}

}  // namespace

ShadedMesh unitRing(float tube, int segments) {
  std::vector<float> circle;
  for (int k = 0; k <= segments; ++k) {
    const float phi = markerTurn(k, segments);
    circle.insert(circle.end(), {std::cos(phi), std::sin(phi), 0.0f});
  }
  ShadedMesh mesh;
  appendTube(circle, 0, segments, {}, TubeStyle{tube, 6, 1}, mesh);
  return mesh;
}

ShadedMesh unitArrow(int sides) {
  ShadedMesh mesh;
  const std::vector<float> shaft{0.0f, 0.0f, 0.0f, 0.0f, 0.0f, kArrowShaftEnd};
  appendTube(shaft, 0, 1, {}, TubeStyle{1.0f, sides, 1}, mesh);
  // the cone: a ring at its base and the point, each side with its own slanted normal
  const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
  const float slope = kArrowConeRadius / (1.0f - kArrowShaftEnd);
  for (int s = 0; s < sides; ++s) {
    const float phi = markerTurn(s, sides);
    const float c = std::cos(phi);
    const float n = std::sin(phi);
    // the gradient of r − R + slope (z − z0), r the distance from the axis
    const float len = std::sqrt(1.0f + slope * slope);
    pushMarkerVertex(mesh, kArrowConeRadius * c, kArrowConeRadius * n, kArrowShaftEnd, c / len, n / len, slope / len);
    pushMarkerVertex(mesh, 0.0f, 0.0f, 1.0f, c / len, n / len, slope / len);
  }
  for (int s = 0; s < sides; ++s) {
    const std::uint32_t a = first + 2 * static_cast<std::uint32_t>(s);
    const std::uint32_t b = first + 2 * static_cast<std::uint32_t>((s + 1) % sides);
    mesh.indices.insert(mesh.indices.end(), {a, b, a + 1});
  }
  return mesh;
}

}  // namespace microsim::gui
