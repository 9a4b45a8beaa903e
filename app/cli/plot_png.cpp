#include "cli/plot_png.h"

#include "cli/output_file.h"

#include <QBuffer>
#include <QImage>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>
#include <limits>

namespace microsim::cli {

namespace {

constexpr int kWidth = 960;
constexpr int kPanelHeight = 560;
constexpr int kMarginLeft = 90;
constexpr int kMarginRight = 220;
constexpr int kMarginTop = 50;
constexpr int kMarginBottom = 60;

const QColor kPalette[] = {QColor(0x1f, 0x77, 0xb4), QColor(0xd6, 0x27, 0x28), QColor(0x2c, 0xa0, 0x2c),
                           QColor(0xff, 0x7f, 0x0e), QColor(0x94, 0x67, 0xbd), QColor(0x8c, 0x56, 0x4b),
                           QColor(0xe3, 0x77, 0xc2), QColor(0x7f, 0x7f, 0x7f)};

struct Axis {
  double lo = 0.0;
  double hi = 1.0;
  bool log = false;

  double map(double v) const {
    const double a = log ? std::log10(v) : v;
    const double l = log ? std::log10(lo) : lo;
    const double h = log ? std::log10(hi) : hi;
    return (a - l) / (h - l);
  }
};

bool usable(double v, bool log) { return std::isfinite(v) && (!log || v > 0.0); }

Axis fitAxis(const bench::BenchPlot& plot, bool xAxis) {
  Axis axis;
  axis.log = xAxis ? plot.logX : plot.logY;
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (const auto& c : plot.curves) {
    for (double v : xAxis ? c.x : c.y) {
      if (!usable(v, axis.log)) continue;
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
  if (!std::isfinite(lo)) {
    lo = axis.log ? 1.0 : 0.0;
    hi = axis.log ? 10.0 : 1.0;
  }
  if (axis.log) {
    axis.lo = std::pow(10.0, std::floor(std::log10(lo)));
    axis.hi = std::pow(10.0, std::ceil(std::log10(hi)));
    if (axis.hi <= axis.lo) axis.hi = axis.lo * 10.0;
  } else {
    const double span = hi > lo ? hi - lo : std::max(1.0, std::abs(hi));
    axis.lo = lo - 0.05 * span;
    axis.hi = hi + 0.05 * span;
  }
  return axis;
}

QString tickLabel(double v) { return QString::number(v, 'g', 3); }

std::vector<double> ticks(const Axis& axis) {
  std::vector<double> out;
  if (axis.log) {
    const auto decades = static_cast<int>(std::floor(std::log10(axis.hi * 1.0001 / axis.lo)));
    for (int k = 0; k <= decades; ++k) out.push_back(axis.lo * std::pow(10.0, k));
    return out;
  }
  const double raw = (axis.hi - axis.lo) / 6.0;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double step = raw / magnitude < 2.0 ? 2.0 * magnitude : raw / magnitude < 5.0 ? 5.0 * magnitude : 10.0 * magnitude;
  const auto last = std::lround(std::floor(axis.hi / step));
  for (auto k = std::lround(std::ceil(axis.lo / step)); k <= last; ++k) {
    out.push_back(static_cast<double>(k) * step);
  }
  return out;
}

void drawPanel(QPainter& p, const bench::BenchPlot& plot, int top) {
  const QRectF area(kMarginLeft, top + kMarginTop, kWidth - kMarginLeft - kMarginRight,
                    kPanelHeight - kMarginTop - kMarginBottom);
  const Axis ax = fitAxis(plot, true);
  const Axis ay = fitAxis(plot, false);
  auto toPixel = [&](double x, double y) {
    return QPointF(area.left() + ax.map(x) * area.width(), area.bottom() - ay.map(y) * area.height());
  };

  // title, frame, grid and tick labels
  p.setPen(Qt::black);
  QFont font = p.font();
  font.setPointSize(13);
  font.setBold(true);
  p.setFont(font);
  p.drawText(QRectF(0, top + 8, kWidth, 30), Qt::AlignHCenter, QString::fromStdString(plot.title));
  font.setPointSize(9);
  font.setBold(false);
  p.setFont(font);
  p.drawRect(area);
  for (double t : ticks(ax)) {
    const double x = area.left() + ax.map(t) * area.width();
    p.setPen(QColor(225, 225, 225));
    p.drawLine(QPointF(x, area.top()), QPointF(x, area.bottom()));
    p.setPen(Qt::black);
    p.drawText(QRectF(x - 40, area.bottom() + 4, 80, 18), Qt::AlignHCenter, tickLabel(t));
  }
  for (double t : ticks(ay)) {
    const double y = area.bottom() - ay.map(t) * area.height();
    p.setPen(QColor(225, 225, 225));
    p.drawLine(QPointF(area.left(), y), QPointF(area.right(), y));
    p.setPen(Qt::black);
    p.drawText(QRectF(0, y - 9, kMarginLeft - 6, 18), Qt::AlignRight | Qt::AlignVCenter, tickLabel(t));
  }
  p.drawText(QRectF(area.left(), area.bottom() + 26, area.width(), 20), Qt::AlignHCenter,
             QString::fromStdString(plot.xLabel));
  p.save();
  p.translate(18, area.center().y());
  p.rotate(-90);
  p.drawText(QRectF(-area.height() / 2, -10, area.height(), 20), Qt::AlignHCenter,
             QString::fromStdString(plot.yLabel));
  p.restore();

  // curves with markers, clipped to the plot area, and the legend beside it
  int index = 0;
  for (const auto& c : plot.curves) {
    const QColor color = kPalette[index % std::size(kPalette)];
    p.setPen(QPen(color, 2));
    p.setClipRect(area.adjusted(-4, -4, 4, 4));
    QPainterPath path;
    bool started = false;
    for (std::size_t i = 0; i < std::min(c.x.size(), c.y.size()); ++i) {
      if (!usable(c.x[i], ax.log) || !usable(c.y[i], ay.log)) continue;
      const QPointF pt = toPixel(c.x[i], c.y[i]);
      if (started) path.lineTo(pt); else path.moveTo(pt);
      started = true;
      p.drawEllipse(pt, 2.5, 2.5);
    }
    p.drawPath(path);
    p.setClipping(false);
    const double ly = area.top() + 10 + 20 * index;
    p.drawLine(QPointF(area.right() + 12, ly), QPointF(area.right() + 36, ly));
    p.setPen(Qt::black);
    p.drawText(QRectF(area.right() + 42, ly - 9, kMarginRight - 46, 18), Qt::AlignLeft | Qt::AlignVCenter,
               QString::fromStdString(c.label));
    ++index;
  }
}

}  // namespace

bool writePlotPng(const std::vector<bench::BenchPlot>& plots, const QString& file) {
  if (plots.empty()) return false;
  QImage image(kWidth, kPanelHeight * static_cast<int>(plots.size()), QImage::Format_RGB32);
  image.fill(Qt::white);
  QPainter painter(&image);
  painter.setRenderHint(QPainter::Antialiasing);
  for (std::size_t i = 0; i < plots.size(); ++i) drawPanel(painter, plots[i], static_cast<int>(i) * kPanelHeight);
  painter.end();
  // encoded in memory first: QImage::save does not see a full disk
  QByteArray png;
  QBuffer buffer(&png);
  if (!buffer.open(QIODevice::WriteOnly) || !image.save(&buffer, "PNG")) return false;
  QString why;
  return writeOutputFile(file, png, why);
}

}  // namespace microsim::cli
