#include "gui/render/background_plane.h"

#include <QVector3D>
#include <QVector4D>

#include <algorithm>
#include <cmath>

namespace microsim::gui {

namespace {

QVector3D planeVector(const Eigen::Vector3d& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}

}  // namespace

QMatrix4x4 planarShadow(const QVector4D& plane, const QVector4D& light) {
  const float dot = QVector4D::dotProduct(plane, light);
  QMatrix4x4 m;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m(r, c) = (r == c ? dot : 0.0f) - light[r] * plane[c];
  return m;
}

BackgroundPlane backgroundPlane(const sim::SceneDef& def) {
  BackgroundPlane out;
  const QVector3D eye = planeVector(def.camera.eye);
  const QVector3D target = planeVector(def.camera.target);
  const QVector3D f = (target - eye).normalized();
  float farthest = 0.0f;
  const auto& rest = def.tissue.model.restPositions();
  for (Eigen::Index i = 0; i < rest.cols(); ++i)
    farthest = std::max(farthest, QVector3D::dotProduct(planeVector(Eigen::Vector3d(rest.col(i))) - target, f));
  const QVector3D centre = target + (farthest + 1.0f) * f;
  const QVector3D n = -f;
  const QVector3D any = std::abs(n.x()) < 0.9f ? QVector3D(1, 0, 0) : QVector3D(0, 1, 0);
  const QVector3D u = QVector3D::crossProduct(n, any).normalized() * 40.0f;
  const QVector3D w = QVector3D::crossProduct(n, u.normalized()) * 40.0f;
  for (const QVector3D& p : {centre - u - w, centre + u - w, centre + u + w, centre - u + w})
    out.mesh.vertices.push_back({{p.x(), p.y(), p.z()}, {n.x(), n.y(), n.z()}});
  out.mesh.indices = {0, 1, 2, 0, 2, 3};
  const QVector3D up = planeVector(def.camera.up).normalized();
  const QVector3D lightDir = (n + 0.35f * QVector3D::crossProduct(up, n) + 0.5f * up).normalized();
  out.shadow = planarShadow(QVector4D(n, -QVector3D::dotProduct(n, centre)), QVector4D(lightDir, 0.0f));
  return out;
}

}  // namespace microsim::gui
