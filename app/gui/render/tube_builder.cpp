#include "gui/render/tube_builder.h"

#include <QVector3D>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace microsim::gui {

namespace {

QVector3D node(const std::vector<float>& xyz, int i) {
  const auto k = 3 * static_cast<std::size_t>(i);
  return {xyz[k], xyz[k + 1], xyz[k + 2]};
}

QVector3D catmullRom(const QVector3D& p0, const QVector3D& p1, const QVector3D& p2,
                     const QVector3D& p3, float t) {
  const float t2 = t * t;
  const float t3 = t2 * t;
  return 0.5f * ((2.0f * p1) + (p2 - p0) * t + (2.0f * p0 - 5.0f * p1 + 4.0f * p2 - p3) * t2 +
                 (3.0f * p1 - p0 - 3.0f * p2 + p3) * t3);
}

QVector3D anyPerpendicular(const QVector3D& t) {
  const QVector3D axis = std::abs(t.x()) < 0.9f ? QVector3D(1, 0, 0) : QVector3D(0, 1, 0);
  return QVector3D::crossProduct(t, axis).normalized();
}

void pushVertex(ShadedMesh& mesh, const QVector3D& p, const QVector3D& n) {
  mesh.vertices.push_back({{p.x(), p.y(), p.z()}, {n.x(), n.y(), n.z()}});
}

void cap(ShadedMesh& mesh, const QVector3D& centre, const QVector3D& normal, std::uint32_t ring,
         int sides, bool flip) {
  const auto c = static_cast<std::uint32_t>(mesh.vertices.size());
  pushVertex(mesh, centre, normal);
  // the rim again, with the cap's normal, so the cap reads flat
  for (int s = 0; s < sides; ++s) {
    const ShadedVertex& v = mesh.vertices[ring + static_cast<std::uint32_t>(s)];
    pushVertex(mesh, {v.position[0], v.position[1], v.position[2]}, normal);
  }
  for (int s = 0; s < sides; ++s) {
    const std::uint32_t a = c + 1 + static_cast<std::uint32_t>(s);
    const std::uint32_t b = c + 1 + static_cast<std::uint32_t>((s + 1) % sides);
    if (flip) mesh.indices.insert(mesh.indices.end(), {c, b, a});
    else mesh.indices.insert(mesh.indices.end(), {c, a, b});
  }
}

// one tube over the intact run of nodes [a, b]
void appendRun(const std::vector<float>& xyz, int a, int b, const TubeStyle& style, ShadedMesh& mesh) {
  const int sub = std::max(1, style.subdivisions);
  std::vector<QVector3D> path;
  path.reserve(static_cast<std::size_t>(b - a) * static_cast<std::size_t>(sub) + 1);
  for (int i = a; i < b; ++i) {
    const QVector3D p0 = node(xyz, std::max(a, i - 1));
    const QVector3D p1 = node(xyz, i);
    const QVector3D p2 = node(xyz, i + 1);
    const QVector3D p3 = node(xyz, std::min(b, i + 2));
    for (int s = 0; s < sub; ++s) path.push_back(catmullRom(p0, p1, p2, p3, static_cast<float>(s) / static_cast<float>(sub)));
  }
  path.push_back(node(xyz, b));

  const int sides = std::max(3, style.sides);
  const auto firstRing = static_cast<std::uint32_t>(mesh.vertices.size());
  QVector3D normal;
  QVector3D tangent;
  for (std::size_t k = 0; k < path.size(); ++k) {
    const QVector3D& before = path[k == 0 ? 0 : k - 1];
    const QVector3D& after = path[std::min(k + 1, path.size() - 1)];
    QVector3D t = (after - before).normalized();
    if (t.isNull()) t = tangent.isNull() ? QVector3D(1, 0, 0) : tangent;
    if (k == 0) {
      normal = anyPerpendicular(t);
    } else {
      // parallel transport: remove the new tangent's component, keep the frame untwisted
      normal = (normal - QVector3D::dotProduct(normal, t) * t).normalized();
      if (normal.isNull()) normal = anyPerpendicular(t);
    }
    tangent = t;
    const QVector3D binormal = QVector3D::crossProduct(t, normal);
    for (int s = 0; s < sides; ++s) {
      const float phi = 2.0f * std::numbers::pi_v<float> * static_cast<float>(s) / static_cast<float>(sides);
      const QVector3D n = std::cos(phi) * normal + std::sin(phi) * binormal;
      pushVertex(mesh, path[k] + style.radius * n, n);
    }
  }
  const auto rings = static_cast<std::uint32_t>(path.size());
  const auto n = static_cast<std::uint32_t>(sides);
  for (std::uint32_t k = 0; k + 1 < rings; ++k) {
    for (std::uint32_t s = 0; s < n; ++s) {
      const std::uint32_t a0 = firstRing + k * n + s;
      const std::uint32_t a1 = firstRing + k * n + (s + 1) % n;
      const std::uint32_t b0 = a0 + n;
      const std::uint32_t b1 = a1 + n;
      mesh.indices.insert(mesh.indices.end(), {a0, a1, b1, a0, b1, b0});
    }
  }
  const QVector3D startTangent = (path[std::min<std::size_t>(1, path.size() - 1)] - path[0]).normalized();
  cap(mesh, path.front(), -startTangent, firstRing, sides, true);
  cap(mesh, path.back(), tangent, firstRing + (rings - 1) * n, sides, false);
}

}  // namespace

void appendTube(const std::vector<float>& xyz, int first, int last,
                const std::vector<std::uint8_t>& alive, const TubeStyle& style, ShadedMesh& mesh) {
  const int nodes = static_cast<int>(xyz.size() / 3);
  first = std::max(0, first);
  last = std::min(last, nodes - 1);
  int runStart = first;
  for (int i = first; i < last; ++i) {
    const bool intact = alive.empty() || static_cast<std::size_t>(i) >= alive.size() || alive[static_cast<std::size_t>(i)] != 0;
    if (!intact) {
      if (i > runStart) appendRun(xyz, runStart, i, style, mesh);
      runStart = i + 1;
    }
  }
  if (last > runStart) appendRun(xyz, runStart, last, style, mesh);
}

}  // namespace microsim::gui
