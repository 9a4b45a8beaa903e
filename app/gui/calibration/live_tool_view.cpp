#include "gui/calibration/live_tool_view.h"

#include "gui/number_format.h"

#include "tracking/tracker_source.h"

#include <QPainter>
#include <QPainterPath>

namespace microsim::gui {

LiveToolView::LiveToolView(QWidget* parent) : QWidget(parent) {
  setMinimumSize(240, 140);
  setAttribute(Qt::WA_OpaquePaintEvent);
}

void LiveToolView::setSource(tracking::TrackerSource* source) {
  if (source_ != nullptr) disconnect(source_, nullptr, this, nullptr);
  source_ = source;
  if (source_ != nullptr) connect(source_, &tracking::TrackerSource::poseAccepted, this, &LiveToolView::onPose);
}

void LiveToolView::setCalibration(const tracking::DeviceMapping& mapping,
                                  const calibration::SetupCalibration& calibration) {
  assembler_ = tracking::FrameAssembler(mapping);
  calibration_ = calibration;
  for (auto& t : trails_) t.clear();
  update();
}

std::optional<Eigen::Vector3d> LiveToolView::tip(sim::Hand hand) const {
  const auto& trail = trails_[static_cast<int>(hand)];
  if (trail.empty()) return std::nullopt;
  return trail.back().tip;
}

void LiveToolView::onPose(const tracking::RawPose& pose) {
  const std::optional<sim::InputFrame> frame = assembler_.applyPose(pose, pose.time);
  if (!frame) return;
  const sim::InputFrame scene = calibration::toScene(*frame, calibration_);
  const int h = static_cast<int>(*assembler_.mapping().handForDevice(pose.device));
  auto& trail = trails_[h];
  trail.push_back({pose.time, scene.hands[h].position});
  while (!trail.empty() && (trail.front().time < pose.time - 1.0 || trail.front().time > pose.time)) trail.pop_front();
  update();
}

void LiveToolView::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.fillRect(rect(), palette().base());
  p.setRenderHint(QPainter::Antialiasing);
  const QColor colours[sim::kHandCount] = {QColor(40, 110, 220), QColor(220, 80, 40)};
  const Eigen::Vector3d centre = calibration_.scaling.anchor;
  const int w = width() / 2;

  // two panels: x–y from above, x–z from the side
  const std::array<std::pair<int, QString>, 2> panels = {std::pair{1, tr("top (x–y)")}, std::pair{2, tr("side (x–z)")}};
  for (int panel = 0; panel < 2; ++panel) {
    const QRectF box(panel * w + 4, 4, w - 8, height() - 8);
    const double scale = std::min(box.width(), box.height()) / (2.0 * rangeMm_);
    const auto map = [&](const Eigen::Vector3d& v) {
      const int vertical = panels[static_cast<std::size_t>(panel)].first;
      return QPointF(box.center().x() + (v.x() - centre.x()) * scale,
                     box.center().y() - (v(vertical) - centre(vertical)) * scale);
    };
    p.setPen(palette().mid().color());
    p.drawRect(box);
    p.drawLine(QPointF(box.left(), box.center().y()), QPointF(box.right(), box.center().y()));
    p.drawLine(QPointF(box.center().x(), box.top()), QPointF(box.center().x(), box.bottom()));
    p.setPen(palette().text().color());
    p.drawText(box.adjusted(4, 2, -4, -2), Qt::AlignTop | Qt::AlignLeft,
               panels[static_cast<std::size_t>(panel)].second + QStringLiteral("  ±%1 mm").arg(NumberFormat::number(rangeMm_, 0)));
    for (int h = 0; h < sim::kHandCount; ++h) {
      const auto& trail = trails_[h];
      if (trail.empty()) continue;
      QPainterPath path(map(trail.front().tip));
      for (const Sample& s : trail) path.lineTo(map(s.tip));
      p.setPen(QPen(colours[h], 1.5));
      p.setBrush(Qt::NoBrush);
      p.drawPath(path);
      p.setBrush(colours[h]);
      p.drawEllipse(map(trail.back().tip), 4.0, 4.0);
    }
  }
}

}  // namespace microsim::gui
