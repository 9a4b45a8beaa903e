#include "gui/pages/opened_vessel_image.h"

#include "gui/pages/label_place.h"
#include "i18n/end_product_words.h"

#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>
#include <QPolygonF>

#include <algorithm>
#include <cmath>
#include <limits>

namespace microsim::gui {

namespace {

using assessment::EndProductErrorKind;

constexpr double kPad = 4.0;          // px round the picture
constexpr double kDotRadius = 3.5;    // px, a passage
constexpr double kLabelGap = 2.0;     // px between a marker and its number
constexpr double kWallsAtEdge = 4.0;  // wall thicknesses of bite at the wall's top and bottom edge

const QColor kBackground(0xf7, 0xf4, 0xef);
const QColor kFrontWall(0xf3, 0xc9, 0xc4);
const QColor kBackWall(0xd9, 0xa0, 0x9a);
const QColor kWallEdge(0xc8, 0x4b, 0x4b);
const QColor kThread(0x1f, 0x3b, 0x8c);
const QColor kText(0x33, 0x33, 0x33);

enum class Shape {
  Cross,
  Square,
  Diamond,
  TriangleUp,
  TriangleDown,
  Circle,
  Star,
  Plus,
  Hourglass,
  Ring
};

struct KindStyle {
  QColor colour;
  Shape shape;
};

KindStyle styleOf(EndProductErrorKind kind) {
  using K = EndProductErrorKind;
  switch (kind) {
    case K::SutureLineDisruption:
      return {QColor(0xc6, 0x28, 0x28), Shape::Cross};
    case K::BackWallStitch:
      return {QColor(0x6a, 0x1b, 0x9a), Shape::Square};
    case K::ObliqueStitch:
      return {QColor(0xe6, 0x51, 0x00), Shape::Diamond};
    case K::WideBite:
      return {QColor(0x15, 0x65, 0xc0), Shape::TriangleUp};
    case K::PartialThicknessBite:
      return {QColor(0x00, 0x79, 0x6b), Shape::TriangleDown};
    case K::UnequalSpacing:
      return {QColor(0x6d, 0x4c, 0x41), Shape::Circle};
    case K::WallTear:
      return {QColor(0xad, 0x14, 0x57), Shape::Star};
    case K::OverTightStitch:
      return {QColor(0x45, 0x5a, 0x64), Shape::Ring};
    case K::ThreadInLumen:
      return {QColor(0x45, 0x5a, 0x64), Shape::Plus};
    case K::LargeEdgeOverlap:
      return {QColor(0x45, 0x5a, 0x64), Shape::Hourglass};
  }
  return {kText, Shape::Circle};
}

QFont labelFont(QSize size) {
  QFont font;
  font.setPixelSize(std::max(10, size.height() / 24));
  return font;
}

double markerRadius(QSize size) {
  return std::max(6.0, size.height() / 48.0);
}

double xOf(const QRectF& wall, double deg) {
  const double wrapped = std::fmod(std::fmod(deg, 360.0) + 360.0, 360.0);
  return wall.left() + wall.width() * wrapped / 360.0;
}

// the signed smaller turn from a to b, (−180, 180] degrees
double turnDeg(double a, double b) {
  double d = std::fmod(b - a, 360.0);
  if (d > 180.0) d -= 360.0;
  if (d <= -180.0) d += 360.0;
  return d;
}

bool located(QPointF p) {
  return std::isfinite(p.x()) && std::isfinite(p.y());
}

QRectF around(QPointF at, double radius) {
  return {at - QPointF(radius, radius), QSizeF(2 * radius, 2 * radius)};
}

QSizeF textExtent(const QFontMetricsF& metrics, const QString& text) {
  return {std::ceil(metrics.horizontalAdvance(text)) + 2.0, std::ceil(metrics.height())};
}

// a passage's place: its angle across, its bite away from the suture line on its end's side
QPointF passagePoint(const assessment::PierceMetrics& p, const QRectF& wall, double line) {
  if (!std::isfinite(p.circumferenceDeg)) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {nan, nan};
  }
  const double walls =
      std::isfinite(p.biteWalls) ? std::clamp(p.biteWalls, 0.0, kWallsAtEdge) : 0.5 * kWallsAtEdge;
  const double away = (0.12 + 0.83 * walls / kWallsAtEdge) * 0.5 * wall.height();
  return {xOf(wall, p.circumferenceDeg), p.end == 1 ? line + away : line - away};
}

void drawMarker(QPainter& painter, Shape shape, QPointF c, double r) {
  const double s = 0.8 * r;
  switch (shape) {
    case Shape::Cross:
      painter.drawLine(c + QPointF(-s, -s), c + QPointF(s, s));
      painter.drawLine(c + QPointF(-s, s), c + QPointF(s, -s));
      return;
    case Shape::Plus:
      painter.drawLine(c + QPointF(-r, 0), c + QPointF(r, 0));
      painter.drawLine(c + QPointF(0, -r), c + QPointF(0, r));
      return;
    case Shape::Square:
      painter.drawRect(QRectF(c - QPointF(s, s), QSizeF(2 * s, 2 * s)));
      return;
    case Shape::Diamond:
      painter.drawPolygon(QPolygonF(
          {c + QPointF(0, -r), c + QPointF(r, 0), c + QPointF(0, r), c + QPointF(-r, 0)}));
      return;
    case Shape::TriangleUp:
      painter.drawPolygon(
          QPolygonF({c + QPointF(0, -r), c + QPointF(r, 0.8 * r), c + QPointF(-r, 0.8 * r)}));
      return;
    case Shape::TriangleDown:
      painter.drawPolygon(
          QPolygonF({c + QPointF(0, r), c + QPointF(r, -0.8 * r), c + QPointF(-r, -0.8 * r)}));
      return;
    case Shape::Hourglass:
      painter.drawPolygon(QPolygonF(
          {c + QPointF(-s, -r), c + QPointF(s, -r), c + QPointF(-s, r), c + QPointF(s, r)}));
      return;
    case Shape::Star: {
      QPolygonF star;
      for (int k = 0; k < 10; ++k) {
        const double angle = -M_PI / 2 + k * M_PI / 5;
        const double radius = k % 2 == 0 ? r : 0.45 * r;
        star << c + QPointF(radius * std::cos(angle), radius * std::sin(angle));
      }
      painter.drawPolygon(star);
      return;
    }
    case Shape::Ring:
      painter.drawEllipse(c, r, r);
      painter.drawEllipse(c, 0.4 * r, 0.4 * r);
      return;
    case Shape::Circle:
      painter.drawEllipse(c, r, r);
      return;
  }
}

// a label level with its mark (right, then left) where that covers nothing, so that markers
// stacked on one passage each have their number beside them; else where freeLabelPlace finds
QRectF labelPlace(QPointF at, QSizeF extent, double clearance, bool above, const std::vector<QRectF>& taken,
                  const QRectF& bounds) {
  const double top = at.y() - extent.height() / 2;
  for (const QRectF& c : {QRectF(QPointF(at.x() + clearance, top), extent),
                          QRectF(QPointF(at.x() - clearance - extent.width(), top), extent)}) {
    if (bounds.contains(c) && std::none_of(taken.begin(), taken.end(), [&c](const QRectF& t) { return t.intersects(c); }))
      return c;
  }
  return freeLabelPlace(at, extent, clearance, above, taken, bounds);
}

// the legend's rows under the wall: a sample marker and the kind in words for each kind with a
// located error, flowing left to right; then the errors that are not located
struct Legend {
  std::vector<OpenedVesselLayout::LegendEntry> entries;
  std::vector<int> unlocated;
  OpenedVesselLayout::Text unlocatedText;
  double height = 0.0;
};

Legend layOutLegend(const OpenedVessel& v, const QFontMetricsF& metrics, double r, double left,
                    double width, double top) {
  Legend legend;
  std::vector<EndProductErrorKind> kinds;
  for (std::size_t i = 0; i < v.errors.size(); ++i) {
    const assessment::EndProductError& e = v.errors[i];
    if (!std::isfinite(e.angleDeg)) {
      legend.unlocated.push_back(static_cast<int>(i));
      continue;
    }
    if (std::find(kinds.begin(), kinds.end(), e.kind) == kinds.end()) kinds.push_back(e.kind);
  }
  std::sort(kinds.begin(), kinds.end());

  const double rowHeight = std::max(std::ceil(metrics.height()), 2 * r) + 3.0;
  double x = left;
  double y = top;
  for (const EndProductErrorKind kind : kinds) {
    const QString text = i18n::EndProductWords::kind(kind);
    const QSizeF extent = textExtent(metrics, text);
    const double entryWidth = 2 * r + 4.0 + extent.width();
    if (x > left && x + entryWidth > left + width) {
      x = left;
      y += rowHeight;
    }
    const QPointF marker(x + r, y + rowHeight / 2);
    const QRectF textRect(
        QPointF(x + 2 * r + 4.0, y + (rowHeight - extent.height()) / 2),
        QSizeF(std::min(extent.width(), left + width - x - 2 * r - 4.0), extent.height()));
    legend.entries.push_back({kind, marker, {text, textRect}});
    x += entryWidth + 12.0;
  }
  if (!kinds.empty()) y += rowHeight;

  if (!legend.unlocated.empty()) {
    QStringList items;
    for (const int i : legend.unlocated)
      items << OpenedVesselImage::tr("%1 (%2)",
                                     "an error not located: its kind, its number in the error list")
                   .arg(i18n::EndProductWords::kind(v.errors[std::size_t(i)].kind))
                   .arg(i + 1);
    const QString text =
        OpenedVesselImage::tr("Not located: %1").arg(items.join(QStringLiteral(", ")));
    const QRectF rect =
        metrics.boundingRect(QRectF(left, y, width, 1e4), Qt::TextWordWrap | Qt::AlignLeft, text);
    legend.unlocatedText = {text, QRectF(rect.topLeft(), QSizeF(width, std::ceil(rect.height())))};
    y += std::ceil(rect.height()) + 2.0;
  }
  legend.height = y - top;
  return legend;
}

}  // namespace

OpenedVesselLayout OpenedVesselImage::layOut(const OpenedVessel& v, QSize size) {
  OpenedVesselLayout out;
  const QFontMetricsF metrics(labelFont(size));
  const double lineHeight = std::ceil(metrics.height());
  const double r = markerRadius(size);

  // margins: the ends' names at the left, half of "360°" at the right
  const QString endAbove = tr("end 1");
  const QString endBelow = tr("end 2");
  const double endWidth =
      std::max(textExtent(metrics, endAbove).width(), textExtent(metrics, endBelow).width());
  const double left =
      kPad + std::max(endWidth + 4.0, textExtent(metrics, QStringLiteral("0°")).width() / 2);
  const double right = kPad + textExtent(metrics, QStringLiteral("360°")).width() / 2;
  const double width = std::max(40.0, size.width() - left - right);

  // the legend first: what is left above it is the wall's
  const double top = kPad + lineHeight + 3.0;
  const Legend probe = layOutLegend(v, metrics, r, kPad, size.width() - 2 * kPad, 0.0);
  const double below = lineHeight + 4.0 + probe.height + kPad;
  out.wall = QRectF(left, top, width, std::max(4.0 * lineHeight, size.height() - top - below));
  out.sutureLineY = out.wall.center().y();
  Legend legend = layOutLegend(v, metrics, r, kPad, size.width() - 2 * kPad,
                               out.wall.bottom() + lineHeight + 4.0);
  out.legend = std::move(legend.entries);
  out.unlocated = std::move(legend.unlocated);
  out.unlocatedText = std::move(legend.unlocatedText);

  // the circumference above, the walls and the ends' names
  for (const int deg : {0, 90, 180, 270, 360}) {
    const QString text = tr("%1°", "an angle round the vessel").arg(deg);
    const QSizeF extent = textExtent(metrics, text);
    out.axisLabels.push_back(
        {text, QRectF(QPointF(xOf(out.wall, deg) - extent.width() / 2, kPad), extent)});
  }
  out.axisLabels.back().rect.moveLeft(out.wall.right() - out.axisLabels.back().rect.width() / 2);
  const auto wallName = [&](const QString& text, double centreDeg, double spanDeg) {
    const double span = out.wall.width() * spanDeg / 360.0 - 4.0;
    const QString shown = metrics.elidedText(text, Qt::ElideRight, span);
    const QSizeF extent = textExtent(metrics, shown);
    const double x = out.wall.left() + out.wall.width() * centreDeg / 360.0 - extent.width() / 2;
    out.wallNames.push_back({shown, QRectF(QPointF(x, out.wall.bottom() + 2.0), extent)});
  };
  wallName(tr("front wall"), 45.0, 90.0);
  wallName(tr("back wall"), 180.0, 180.0);
  wallName(tr("front wall"), 315.0, 90.0);
  for (const auto& [text, y] : {std::pair{endAbove, out.sutureLineY - out.wall.height() / 4},
                                std::pair{endBelow, out.sutureLineY + out.wall.height() / 4}}) {
    const QSizeF extent = textExtent(metrics, text);
    out.wallNames.push_back(
        {text,
         QRectF(QPointF(out.wall.left() - 4.0 - extent.width(), y - extent.height() / 2), extent)});
  }

  // passages, and every dot an obstacle for the labels
  std::vector<QRectF> taken;
  for (const assessment::PierceMetrics& p : v.passages) {
    out.passages.push_back(passagePoint(p, out.wall, out.sutureLineY));
    if (located(out.passages.back())) taken.push_back(around(out.passages.back(), kDotRadius));
  }

  // located errors: on their passage, else on the suture line; a repeat at one place stacks
  std::vector<QPointF> anchors;
  for (std::size_t i = 0; i < v.errors.size(); ++i) {
    const assessment::EndProductError& e = v.errors[i];
    if (!std::isfinite(e.angleDeg)) continue;
    QPointF anchor(xOf(out.wall, e.angleDeg), out.sutureLineY);
    if (e.passage >= 0 && std::size_t(e.passage) < out.passages.size() &&
        located(out.passages[std::size_t(e.passage)]))
      anchor.setY(out.passages[std::size_t(e.passage)].y());
    const auto repeats = std::count_if(anchors.begin(), anchors.end(), [&anchor](QPointF a) {
      return std::abs(a.x() - anchor.x()) < 0.5 && std::abs(a.y() - anchor.y()) < 0.5;
    });
    anchors.push_back(anchor);
    const double away = anchor.y() > out.sutureLineY + 0.5 ? 1.0 : -1.0;
    QPointF at = anchor + QPointF(0, away * double(repeats) * (2 * r + 2.0));
    at.setY(std::clamp(at.y(), out.wall.top() + r, out.wall.bottom() - r));
    out.marks.push_back({static_cast<int>(i), at, QString::number(i + 1), {}});
    taken.push_back(around(at, r));
  }

  // the threads cross the suture line between their passages, the short way round
  for (std::size_t s = 0; s < v.stitches.size(); ++s) {
    const assessment::StitchMetrics& st = v.stitches[s];
    if (st.first < 0 || st.second < 0 ||
        std::size_t(std::max(st.first, st.second)) >= out.passages.size())
      continue;
    const QPointF a = out.passages[std::size_t(st.first)];
    const QPointF b = out.passages[std::size_t(st.second)];
    if (!located(a) || !located(b)) continue;
    const double d = turnDeg(v.passages[std::size_t(st.first)].circumferenceDeg,
                             v.passages[std::size_t(st.second)].circumferenceDeg);
    const double bx = a.x() + out.wall.width() * d / 360.0;
    const double t =
        std::abs(b.y() - a.y()) > 1e-9 ? (out.sutureLineY - a.y()) / (b.y() - a.y()) : 0.5;
    const double crossing = a.x() + std::clamp(t, 0.0, 1.0) * (bx - a.x());
    // across the seam the thread leaves one edge and comes in at the other: two pieces
    out.threads.emplace_back(a, QPointF(bx, b.y()));
    if (std::abs(bx - b.x()) > 0.5)
      out.threads.emplace_back(QPointF(b.x() - (bx - a.x()), a.y()), b);
    const double wrapped =
        out.wall.left() +
        std::fmod(std::fmod(crossing - out.wall.left(), out.wall.width()) + out.wall.width(),
                  out.wall.width());
    out.stitchLabels.push_back({QPointF(wrapped, out.sutureLineY),
                                tr("S%1", "stitch number on the opened vessel").arg(s + 1),
                                {}});
  }

  // labels: the errors' numbers first, then the stitches', each where it covers nothing placed
  for (OpenedVesselLayout::Mark& m : out.marks) {
    const QSizeF extent = textExtent(metrics, m.label);
    m.labelRect = labelPlace(m.at, extent, r + kLabelGap, m.at.y() <= out.sutureLineY, taken, out.wall);
    taken.push_back(m.labelRect);
  }
  for (OpenedVesselLayout::StitchLabel& l : out.stitchLabels) {
    const QSizeF extent = textExtent(metrics, l.label);
    l.labelRect = freeLabelPlace(l.at, extent, kDotRadius + kLabelGap, false, taken, out.wall);
    taken.push_back(l.labelRect);
  }
  return out;
}

QImage OpenedVesselImage::draw(const OpenedVessel& v, QSize size, qreal pixelRatio) {
  QImage image(size * pixelRatio, QImage::Format_ARGB32_Premultiplied);
  image.setDevicePixelRatio(pixelRatio);
  image.fill(kBackground);
  const OpenedVesselLayout layout = layOut(v, size);
  const QRectF& wall = layout.wall;
  const double r = markerRadius(size);
  QPainter painter(&image);
  painter.setRenderHint(QPainter::Antialiasing);
  painter.setFont(labelFont(size));

  // the wall: the back half darker, its bounds dashed, the suture line across
  painter.setPen(Qt::NoPen);
  painter.fillRect(wall, kFrontWall);
  painter.fillRect(
      QRectF(QPointF(xOf(wall, 90), wall.top()), QPointF(xOf(wall, 270), wall.bottom())),
      kBackWall);
  painter.setPen(QPen(kWallEdge, 1, Qt::DashLine));
  for (const double deg : {90.0, 270.0})
    painter.drawLine(QPointF(xOf(wall, deg), wall.top()), QPointF(xOf(wall, deg), wall.bottom()));
  painter.setPen(QPen(kWallEdge, 1));
  painter.setBrush(Qt::NoBrush);
  painter.drawRect(wall);
  for (const int deg : {0, 90, 180, 270, 360}) {
    const double x = deg == 360 ? wall.right() : xOf(wall, deg);
    painter.drawLine(QPointF(x, wall.top() - 3.0), QPointF(x, wall.top()));
  }
  painter.setPen(QPen(QColor(0x5a, 0x2a, 0x2a), 2));
  painter.drawLine(QPointF(wall.left(), layout.sutureLineY),
                   QPointF(wall.right(), layout.sutureLineY));

  // the threads, clipped to the wall
  painter.save();
  painter.setClipRect(wall);
  painter.setPen(QPen(kThread, 2));
  for (const QLineF& thread : layout.threads) painter.drawLine(thread);
  painter.restore();
  painter.setPen(QPen(Qt::white, 1));
  painter.setBrush(kThread);
  for (const QPointF& p : layout.passages)
    if (located(p)) painter.drawEllipse(p, kDotRadius, kDotRadius);

  // the errors' markers, then every label over them
  for (const OpenedVesselLayout::Mark& m : layout.marks) {
    const KindStyle style = styleOf(v.errors[std::size_t(m.error)].kind);
    QColor fill = style.colour;
    fill.setAlpha(45);
    painter.setPen(QPen(style.colour, 2));
    painter.setBrush(fill);
    drawMarker(painter, style.shape, m.at, r);
  }
  const QColor backing(0xf7, 0xf4, 0xef, 210);
  QFont bold = labelFont(size);
  bold.setBold(true);
  for (const OpenedVesselLayout::Mark& m : layout.marks) {
    painter.fillRect(m.labelRect, backing);
    painter.setPen(styleOf(v.errors[std::size_t(m.error)].kind).colour);
    painter.setFont(bold);
    painter.drawText(m.labelRect, Qt::AlignCenter, m.label);
  }
  painter.setFont(labelFont(size));
  for (const OpenedVesselLayout::StitchLabel& l : layout.stitchLabels) {
    painter.fillRect(l.labelRect, backing);
    painter.setPen(kThread);
    painter.drawText(l.labelRect, Qt::AlignCenter, l.label);
  }
  painter.setPen(kText);
  for (const OpenedVesselLayout::Text& t : layout.axisLabels)
    painter.drawText(t.rect, Qt::AlignCenter, t.text);
  for (const OpenedVesselLayout::Text& t : layout.wallNames)
    painter.drawText(t.rect, Qt::AlignCenter, t.text);

  // the legend: each kind's marker and name, then what is not located
  for (const OpenedVesselLayout::LegendEntry& e : layout.legend) {
    const KindStyle style = styleOf(e.kind);
    QColor fill = style.colour;
    fill.setAlpha(45);
    painter.setPen(QPen(style.colour, 2));
    painter.setBrush(fill);
    drawMarker(painter, style.shape, e.marker, r);
    painter.setPen(kText);
    painter.drawText(e.text.rect, Qt::AlignLeft | Qt::AlignVCenter, e.text.text);
  }
  if (!layout.unlocatedText.text.isEmpty()) {
    painter.setPen(QColor(0xb0, 0x00, 0x20));
    painter.drawText(layout.unlocatedText.rect, Qt::TextWordWrap | Qt::AlignLeft,
                     layout.unlocatedText.text);
  }
  painter.end();
  return image;
}

}  // namespace microsim::gui
