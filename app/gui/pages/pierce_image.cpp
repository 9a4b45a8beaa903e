#include "gui/pages/pierce_image.h"

#include "gui/number_format.h"
#include "gui/pages/label_place.h"

#include <QFontMetricsF>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace microsim::gui {

namespace {

// one vessel's wall bands and lumen, in image pixels
struct VesselBands {
  QRectF lumen;
  QRectF upperWall;
  QRectF lowerWall;
};

// one pierce as drawn: its dot, the needle's direction through it and its label
struct PierceMark {
  QPointF at;
  QPointF from;
  QPointF to;
  bool entry = true;
  QString label;
  QRectF labelRect;
};

struct PierceDiagram {
  std::vector<VesselBands> vessels;
  std::vector<PierceMark> marks;
};

constexpr double kPierceDotRadius = 4.0;  // px
constexpr double kPierceLabelGap = 3.0;   // px between a dot and its label

QColor pierceColour(bool entry) { return entry ? QColor(0xd3, 0x2f, 0x2f) : QColor(0x19, 0x5f, 0xc0); }

QFont pierceLabelFont(QSize size) {
  QFont font;
  font.setPixelSize(std::max(10, size.height() / 22));
  return font;
}

PierceDiagram layOutPierceDiagram(const std::vector<sim::VesselDef>& vessels,
                                  const std::vector<sim::PierceEvent>& pierces, QSize size) {
  PierceDiagram diagram;

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
  if (u0 > u1) return diagram;
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
    diagram.vessels.push_back({QRectF(toImage(a, c + v.radius), toImage(b, c - v.radius)),
                               QRectF(toImage(a, c + v.radius), toImage(b, c + v.radius - v.wallThickness)),
                               QRectF(toImage(a, c - v.radius + v.wallThickness), toImage(b, c - v.radius))});
  }

  // pierces: the needle's direction through the point
  const double arm = 0.18;  // mm each side of the point
  for (const sim::PierceEvent& p : pierces) {
    sim::Vec3 t(p.tangent.dot(axis), p.tangent.dot(up), 0.0);
    if (t.norm() < 1e-9) t = sim::Vec3::UnitX();
    t.normalize();
    PierceMark mark;
    mark.at = toImage(u(p.point), w(p.point));
    mark.from = toImage(u(p.point) - arm * t.x(), w(p.point) - arm * t.y());
    mark.to = toImage(u(p.point) + arm * t.x(), w(p.point) + arm * t.y());
    mark.entry = p.entry;
    diagram.marks.push_back(mark);
  }

  // labels: every dot is an obstacle, then each placed label
  const QFontMetricsF metrics(pierceLabelFont(size));
  std::vector<QRectF> taken;
  for (const PierceMark& m : diagram.marks)
    taken.emplace_back(m.at - QPointF(kPierceDotRadius, kPierceDotRadius), QSizeF(2 * kPierceDotRadius, 2 * kPierceDotRadius));
  const QRectF bounds(QPointF(0, 0), QSizeF(size));
  for (std::size_t i = 0; i < diagram.marks.size(); ++i) {
    PierceMark& m = diagram.marks[i];
    m.label = QStringLiteral("%1: %2°").arg(i + 1).arg(NumberFormat::number(pierces[i].angleDeg, 0));
    const QSizeF extent(std::ceil(metrics.horizontalAdvance(m.label)) + 1.0, std::ceil(metrics.height()));
    m.labelRect =
        freeLabelPlace(m.at, extent, kPierceDotRadius + kPierceLabelGap, i % 2 == 0, taken, bounds);
    taken.push_back(m.labelRect);
  }
  return diagram;
}

}  // namespace

QImage drawPierceAngles(const std::vector<sim::VesselDef>& vessels,
                        const std::vector<sim::PierceEvent>& pierces, QSize size) {
  QImage image(size, QImage::Format_ARGB32_Premultiplied);
  image.fill(QColor(0xf7, 0xf4, 0xef));
  const PierceDiagram diagram = layOutPierceDiagram(vessels, pierces, size);
  QPainter painter(&image);
  painter.setRenderHint(QPainter::Antialiasing);

  for (const VesselBands& v : diagram.vessels) {
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(0xf3, 0xc9, 0xc4));
    painter.drawRect(v.lumen);
    painter.setBrush(QColor(0xc8, 0x4b, 0x4b));
    painter.drawRect(v.upperWall);
    painter.drawRect(v.lowerWall);
  }

  // the needle's lines and dots first, so that no line crosses a label drawn later
  for (const PierceMark& m : diagram.marks) {
    const QColor colour = pierceColour(m.entry);
    painter.setPen(QPen(colour, 2));
    painter.drawLine(m.from, m.to);
    painter.setBrush(colour);
    painter.drawEllipse(m.at, kPierceDotRadius, kPierceDotRadius);
  }
  painter.setFont(pierceLabelFont(size));
  for (const PierceMark& m : diagram.marks) {
    const QColor colour = pierceColour(m.entry);
    // a pale backing keeps the label legible where it lies over a wall band
    painter.fillRect(m.labelRect, QColor(0xf7, 0xf4, 0xef, 200));
    painter.setPen(colour);
    painter.drawText(m.labelRect, Qt::AlignLeft | Qt::AlignVCenter, m.label);
  }
  painter.end();
  return image;
}

std::vector<QRectF> pierceLabelRects(const std::vector<sim::VesselDef>& vessels,
                                     const std::vector<sim::PierceEvent>& pierces, QSize size) {
  std::vector<QRectF> rects;
  for (const PierceMark& m : layOutPierceDiagram(vessels, pierces, size).marks) rects.push_back(m.labelRect);
  return rects;
}

}  // namespace microsim::gui
