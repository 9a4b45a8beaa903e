#include "gui/review/replay_timeline.h"

#include <QHelpEvent>
#include <QLocale>
#include <QMouseEvent>
#include <QPainter>
#include <QToolTip>

#include <algorithm>
#include <cstdlib>

namespace microsim::gui {

namespace {
// the slider's groove starts about half a handle in: the marks line up with it
constexpr int kTimelineMargin = 8;
constexpr int kLaneHeight = 9;
constexpr int kLaneGap = 2;
constexpr int kMarkWidth = 3;
constexpr int kHitSlack = 4;  ///< px either side of a mark that still hit it

int laneIndex(ReplayLane lane) { return int(lane); }
}  // namespace

ReplayTimeline::ReplayTimeline(QWidget* parent) : QWidget(parent) {
  setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
  setMouseTracking(true);
}

QSize ReplayTimeline::sizeHint() const { return {400, minimumSizeHint().height()}; }

QSize ReplayTimeline::minimumSizeHint() const {
  const int lanes = int(kReplayLanes.size());
  return {100, lanes * kLaneHeight + (lanes + 1) * kLaneGap};
}

void ReplayTimeline::setMarks(std::vector<ReplayMark> marks, int frameCount) {
  marks_ = std::move(marks);
  frameCount_ = frameCount;
  update();
}

void ReplayTimeline::clear() { setMarks({}, 0); }

void ReplayTimeline::setPosition(int position) {
  if (position == position_) return;
  position_ = position;
  update();
}

int ReplayTimeline::xOf(int position) const {
  const int span = std::max(1, width() - 2 * kTimelineMargin);
  return kTimelineMargin + int(double(span) * double(position) / double(std::max(1, frameCount_)));
}

QRect ReplayTimeline::laneRect(ReplayLane lane) const {
  const int i = laneIndex(lane);
  return {0, kLaneGap + i * (kLaneHeight + kLaneGap), width(), kLaneHeight};
}

int ReplayTimeline::laneAt(int y) const {
  for (ReplayLane lane : kReplayLanes)
    if (y >= laneRect(lane).top() - kLaneGap / 2 && y <= laneRect(lane).bottom() + kLaneGap / 2) return laneIndex(lane);
  return -1;
}

QRect ReplayTimeline::markRect(int index) const {
  const ReplayMark& m = marks_.at(std::size_t(index));
  const QRect lane = laneRect(laneOf(m.kind));
  return {xOf(m.position) - kMarkWidth / 2, lane.top(), kMarkWidth, lane.height()};
}

int ReplayTimeline::markAt(QPoint point) const {
  const int lane = laneAt(point.y());
  if (lane < 0) return -1;
  int best = -1;
  int bestDistance = kHitSlack + 1;
  for (int i = 0; i < int(marks_.size()); ++i) {
    if (laneIndex(laneOf(marks_[std::size_t(i)].kind)) != lane) continue;
    // strictly nearer: of marks drawn on one pixel, the earliest is taken
    const int distance = std::abs(xOf(marks_[std::size_t(i)].position) - point.x());
    if (distance < bestDistance) {
      best = i;
      bestDistance = distance;
    }
  }
  return best;
}

QColor ReplayTimeline::colour(ReplayMarkKind kind) {
  switch (kind) {
    case ReplayMarkKind::PierceEntry: return {0x1b, 0x7f, 0x3b};
    case ReplayMarkKind::PierceExit: return {0x00, 0x89, 0x7b};
    case ReplayMarkKind::Grasp: return {0x35, 0x58, 0xc9};
    case ReplayMarkKind::Release: return {0x8a, 0x94, 0xa6};
    case ReplayMarkKind::OverStretch: return {0xe0, 0x8a, 0x00};
    case ReplayMarkKind::Tear: return {0xc6, 0x28, 0x28};
    case ReplayMarkKind::Cut: return {0x6d, 0x4c, 0x41};
    case ReplayMarkKind::Knot: return {0x7b, 0x1f, 0xa2};
    case ReplayMarkKind::KnotSlipped: return {0xc2, 0x18, 0x5b};
    case ReplayMarkKind::ThreadCut: return {0x45, 0x5a, 0x64};
    case ReplayMarkKind::ThreadTooShort: return {0xbf, 0x36, 0x0c};
    case ReplayMarkKind::GraspEmpty: return {0xd8, 0x1b, 0x60};
    case ReplayMarkKind::SutureBreak: return {0xb7, 0x1c, 0x1c};
    case ReplayMarkKind::SuturePulledOut: return {0xad, 0x14, 0x57};
    case ReplayMarkKind::PierceReleased: return {0xef, 0x6c, 0x00};
  }
  return Qt::black;
}

QString ReplayTimeline::laneName(ReplayLane lane) {
  switch (lane) {
    case ReplayLane::Pierces: return tr("Pierces");
    case ReplayLane::Grasps: return tr("Grasps and releases");
    case ReplayLane::Tissue: return tr("Tissue: over-stretch, tears, cuts");
    case ReplayLane::Knots: return tr("Knots and thread cuts");
    case ReplayLane::Errors: return tr("Errors");
  }
  return {};
}

QString ReplayTimeline::describe(const ReplayMark& mark) {
  QString what;
  switch (mark.kind) {
    case ReplayMarkKind::PierceEntry: what = tr("Pierce %1: the needle enters the wall").arg(mark.pierce + 1); break;
    case ReplayMarkKind::PierceExit: what = tr("Pierce %1: the needle leaves the wall").arg(mark.pierce + 1); break;
    case ReplayMarkKind::Grasp: what = tr("Grasp"); break;
    case ReplayMarkKind::Release: what = tr("Release"); break;
    case ReplayMarkKind::OverStretch: what = tr("Tissue over-stretched"); break;
    case ReplayMarkKind::Tear: what = tr("Tissue torn"); break;
    case ReplayMarkKind::Cut: what = tr("Cut"); break;
    case ReplayMarkKind::Knot: what = tr("Knot"); break;
    case ReplayMarkKind::KnotSlipped: what = tr("The knot slipped"); break;
    case ReplayMarkKind::ThreadCut: what = tr("The scissors cut the thread"); break;
    case ReplayMarkKind::ThreadTooShort: what = tr("The needle was left too little thread to tie"); break;
    case ReplayMarkKind::GraspEmpty: what = tr("The forceps closed on nothing"); break;
    case ReplayMarkKind::SutureBreak: what = tr("The suture broke"); break;
    case ReplayMarkKind::SuturePulledOut: what = tr("Pierce %1: the suture slid out").arg(mark.pierce + 1); break;
    case ReplayMarkKind::PierceReleased:
      what = tr("Pierce %1: the needle left it before the thread").arg(mark.pierce + 1);
      break;
  }
  const QString seconds = QLocale().toString(mark.time, 'f', 2);
  if (mark.hand == 0) return tr("%1 (left hand), %2 s").arg(what, seconds);
  if (mark.hand == 1) return tr("%1 (right hand), %2 s").arg(what, seconds);
  return tr("%1, %2 s").arg(what, seconds);
}

void ReplayTimeline::paintEvent(QPaintEvent*) {
  QPainter p(this);
  // lanes a shade darker than the window, so that an empty one still reads as a lane
  const QColor lane = palette().color(QPalette::Window).darker(108);
  for (ReplayLane l : kReplayLanes) {
    const QRect r = laneRect(l);
    p.fillRect(QRect(kTimelineMargin, r.top(), width() - 2 * kTimelineMargin, r.height()), lane);
  }
  for (int i = 0; i < int(marks_.size()); ++i) p.fillRect(markRect(i), colour(marks_[std::size_t(i)].kind));
  // the playhead over the lanes
  p.setPen(QPen(palette().color(QPalette::Text), 1));
  const int x = xOf(position_);
  p.drawLine(x, 0, x, height() - 1);
}

void ReplayTimeline::mousePressEvent(QMouseEvent* event) {
  const int i = markAt(event->position().toPoint());
  if (event->button() == Qt::LeftButton && i >= 0) {
    Q_EMIT markClicked(marks_[std::size_t(i)].position);
    event->accept();
    return;
  }
  QWidget::mousePressEvent(event);
}

bool ReplayTimeline::event(QEvent* event) {
  if (event->type() == QEvent::ToolTip) {
    auto* help = static_cast<QHelpEvent*>(event);
    const int i = markAt(help->pos());
    const int lane = laneAt(help->pos().y());
    if (i >= 0) QToolTip::showText(help->globalPos(), describe(marks_[std::size_t(i)]), this);
    else if (lane >= 0) QToolTip::showText(help->globalPos(), laneName(kReplayLanes[std::size_t(lane)]), this);
    else QToolTip::hideText();
    return true;
  }
  return QWidget::event(event);
}

}  // namespace microsim::gui
