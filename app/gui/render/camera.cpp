#include "gui/render/camera.h"

#include <QtMath>

#include <algorithm>
#include <cmath>

namespace microsim::gui {

namespace {
QVector3D cameraVector(const sim::Vec3& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}
}  // namespace

MicroscopeCamera::MicroscopeCamera() { reset(sim::CameraDef{}); }

void MicroscopeCamera::reset(const sim::CameraDef& def) {
  home_ = def;
  target_ = cameraVector(def.target);
  const QVector3D toward = cameraVector(def.eye) - target_;
  distance_ = std::max(1e-3f, toward.length());
  fovDeg_ = static_cast<float>(def.fovDeg);
  focus_ = distance_;
  const QVector3D screenUp = cameraVector(def.up).normalized();
  const QVector3D direction = toward.normalized();
  // the microscope is tilted toward the scene's up side; the table is what it tilts over
  const QVector3D untilted = direction - QVector3D::dotProduct(direction, screenUp) * screenUp;
  tableNormal_ = untilted.length() > 1e-3f ? untilted.normalized() : direction;
  look(direction, screenUp);
}

void MicroscopeCamera::showView(NamedView view) {
  reset(home_);
  if (view == NamedView::Microscope) return;
  const QVector3D n = tableNormal_;
  const QVector3D homeUp = cameraVector(home_.up);
  QVector3D back = homeUp - QVector3D::dotProduct(homeUp, n) * n;  // along the table, away from the trainee
  back = back.length() > 1e-3f ? back.normalized() : up();
  const float half = std::sqrt(0.5f);
  switch (view) {
    case NamedView::Top: look(n, back); break;
    case NamedView::Oblique: look(half * n - half * back, back); break;
    case NamedView::Side: look(-back, n); break;
    case NamedView::Microscope: break;
  }
}

void MicroscopeCamera::look(const QVector3D& towardEye, const QVector3D& screenUp) {
  // QQuaternion::fromDirection builds the rotation whose +z is the given direction
  orientation_ = QQuaternion::fromDirection(towardEye.normalized(), screenUp).normalized();
}

QVector3D MicroscopeCamera::forward() const { return orientation_.rotatedVector({0.0f, 0.0f, -1.0f}); }
QVector3D MicroscopeCamera::right() const { return orientation_.rotatedVector({1.0f, 0.0f, 0.0f}); }
QVector3D MicroscopeCamera::up() const { return orientation_.rotatedVector({0.0f, 1.0f, 0.0f}); }
QVector3D MicroscopeCamera::eye() const { return target_ - distance_ * forward(); }

void MicroscopeCamera::orbit(float yawDeg, float pitchDeg) {
  const QQuaternion yaw = QQuaternion::fromAxisAndAngle(tableNormal_, -yawDeg);
  QQuaternion next = yaw * orientation_;
  const QQuaternion pitch = QQuaternion::fromAxisAndAngle(next.rotatedVector({1.0f, 0.0f, 0.0f}), -pitchDeg);
  const QQuaternion pitched = pitch * next;
  // never tip over the pole (the view's up keeps to the back of the table) nor under the table
  constexpr float kSlack = 1e-4f;
  const bool overPole = QVector3D::dotProduct(pitched.rotatedVector({0.0f, 1.0f, 0.0f}), tableNormal_) < -kSlack;
  const bool underTable = QVector3D::dotProduct(pitched.rotatedVector({0.0f, 0.0f, -1.0f}), tableNormal_) > kSlack;
  if (!overPole && !underTable) next = pitched;
  orientation_ = next.normalized();
}

void MicroscopeCamera::pan(float dx, float dy, int height) {
  const float s = mmPerPixel(height);
  target_ += (-dx * s) * right() + (dy * s) * up();
}

void MicroscopeCamera::zoom(float steps) {
  const float before = distance_;
  distance_ = std::clamp(distance_ * std::pow(0.9f, steps), 1.0f, 400.0f);
  focus_ = std::clamp(focus_ + (distance_ - before), nearPlane(), farPlane());
}

void MicroscopeCamera::setFocusDistance(float mm) { focus_ = std::clamp(mm, nearPlane(), farPlane()); }

QMatrix4x4 MicroscopeCamera::view(Eye eye) const {
  QVector3D offset;
  if (eye == Eye::Left) offset = -0.5f * eyeSeparation() * right();
  if (eye == Eye::Right) offset = 0.5f * eyeSeparation() * right();
  const QVector3D from = this->eye() + offset;
  QMatrix4x4 m;
  // parallel eyes; the frustum's shift (projection) converges them on the focal plane
  m.lookAt(from, from + forward(), up());
  return m;
}

QMatrix4x4 MicroscopeCamera::projection(float aspect, Eye eye) const {
  const float n = nearPlane();
  const float top = n * std::tan(qDegreesToRadians(fovDeg_) * 0.5f);
  const float halfWidth = top * aspect;
  float shift = 0.0f;  // frustum shift at the near plane: zero parallax at the focal distance
  if (eye == Eye::Left) shift = 0.5f * eyeSeparation() * n / focus_;
  if (eye == Eye::Right) shift = -0.5f * eyeSeparation() * n / focus_;
  QMatrix4x4 m;
  m.frustum(-halfWidth + shift, halfWidth + shift, -top, top, n, farPlane());
  return m;
}

float MicroscopeCamera::mmPerPixel(int height) const {
  return 2.0f * distance_ * std::tan(qDegreesToRadians(fovDeg_) * 0.5f) / static_cast<float>(std::max(1, height));
}

}  // namespace microsim::gui
