#include "gui/pages/pierce_image.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace microsim::gui {

QImage drawPierceAngles(const std::vector<sim::VesselDef>& vessels,
                        const std::vector<sim::PierceEvent>& pierces, QSize size) {
  QImage image(size, QImage::Format_ARGB32_Premultiplied);
  image.fill(QColor(0xf7, 0xf4, 0xef));
  QPainter painter(&image);
  painter.setRenderHint(QPainter::Antialiasing);

  // side view: u along the first vessel's axis, w toward the microscope (+z) out of the axis
  const sim::Vec3 axis = vessels.empty() ? sim::Vec3::UnitX() : vessels.front().direction.normalized();
  sim::Vec3 up = sim::Vec3::UnitZ() - axis * axis.z();
  if (up.norm() < 1e-6) up = sim::Vec3::UnitY();
  up.normalize();
  auto u = [&](const sim::Vec3& p) { return p.dot(axis); };
  auto w = [&](const sim::Vec3& p) { return p.dot(up); };

  // the extent of everything drawn, in mm
  double u0 = 1e9, u1 = -1e9, w0 = 1e9, w1 = -1e9;
  for (const sim::VesselDef& v : vessels) {
    const sim::Vec3 end = v.origin + v.direction.normalized() * v.length;
    u0 = std::min({u0, u(v.origin), u(end)});
    u1 = std::max({u1, u(v.origin), u(end)});
    w0 = std::min(w0, w(v.origin) - v.radius);
    w1 = std::max(w1, w(v.origin) + v.radius);
  }
  for (const sim::PierceEvent& p : pierces) {
    u0 = std::min(u0, u(p.point));
    u1 = std::max(u1, u(p.point));
    w0 = std::min(w0, w(p.point));
    w1 = std::max(w1, w(p.point));
  }
  if (u0 > u1) {
    painter.end();
    return image;
  }
  const double margin = 0.08 * std::max(u1 - u0, w1 - w0) + 0.1;
  u0 -= margin, u1 += margin, w0 -= margin, w1 += margin;
  const double scale = std::min(size.width() / (u1 - u0), size.height() / (w1 - w0));
  const QPointF offset((size.width() - scale * (u1 - u0)) / 2, (size.height() - scale * (w1 - w0)) / 2);
  auto toImage = [&](double uu, double ww) {
    return QPointF(offset.x() + (uu - u0) * scale, offset.y() + (w1 - ww) * scale);
  };

  // vessels: wall bands around the lumen
  for (const sim::VesselDef& v : vessels) {
    const sim::Vec3 end = v.origin + v.direction.normalized() * v.length;
    const double a = std::min(u(v.origin), u(end)), b = std::max(u(v.origin), u(end));
    const double c = w(v.origin);
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(0xf3, 0xc9, 0xc4));
    painter.drawRect(QRectF(toImage(a, c + v.radius), toImage(b, c - v.radius)));
    painter.setBrush(QColor(0xc8, 0x4b, 0x4b));
    painter.drawRect(QRectF(toImage(a, c + v.radius), toImage(b, c + v.radius - v.wallThickness)));
    painter.drawRect(QRectF(toImage(a, c - v.radius + v.wallThickness), toImage(b, c - v.radius)));
  }

  // pierces: the needle's direction through the point, the angle beside it
  QFont font = painter.font();
  font.setPixelSize(std::max(10, size.height() / 22));
  painter.setFont(font);
  const double arm = 0.18;  // mm each side of the point
  int index = 0;
  for (const sim::PierceEvent& p : pierces) {
    const QColor colour = p.entry ? QColor(0xd3, 0x2f, 0x2f) : QColor(0x19, 0x5f, 0xc0);
    sim::Vec3 t(p.tangent.dot(axis), p.tangent.dot(up), 0.0);
    if (t.norm() < 1e-9) t = sim::Vec3::UnitX();
    t.normalize();
    const QPointF at = toImage(u(p.point), w(p.point));
    const QPointF from = toImage(u(p.point) - arm * t.x(), w(p.point) - arm * t.y());
    const QPointF to = toImage(u(p.point) + arm * t.x(), w(p.point) + arm * t.y());
    painter.setPen(QPen(colour, 2));
    painter.drawLine(from, to);
    painter.setBrush(colour);
    painter.drawEllipse(at, 4, 4);
    const QString label = QStringLiteral("%1: %2°").arg(++index).arg(p.angleDeg, 0, 'f', 0);
    const double side = (index % 2 == 0) ? 1.0 : -1.0;
    painter.drawText(at + QPointF(6, side * font.pixelSize() * 1.4), label);
  }
  painter.end();
  return image;
}

}  // namespace microsim::gui
