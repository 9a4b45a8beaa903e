#include "tracking/manual_source.h"

#include "tracking/instrument_switch.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace microsim::tracking {

namespace {

// a tool whose +x (from the tip back to the hinge) points along `back`, its jaws opening
// about `up`
Eigen::Quaterniond toolOrientation(const Eigen::Vector3d& back, const Eigen::Vector3d& up) {
  const Eigen::Vector3d x = back.normalized();
  Eigen::Vector3d y = up - up.dot(x) * x;
  if (y.norm() < 1e-9) y = x.unitOrthogonal();
  y.normalize();
  Eigen::Matrix3d r;
  r.col(0) = x;
  r.col(1) = y;
  r.col(2) = x.cross(y);
  return Eigen::Quaterniond(r).normalized();
}

}  // namespace

ManualSource::ManualSource(QObject* parent) : TrackerSource(parent) {
  placeTools(sim::SceneDef{});
}

void ManualSource::start() {
  if (running_) return;
  clock_.start();
  running_ = true;
  Q_EMIT connectedChanged(true);
  emitFrame();
}

void ManualSource::stop() {
  if (!running_) return;
  running_ = false;
  Q_EMIT connectedChanged(false);
}

TrackerStatus ManualSource::status() const {
  TrackerStatus s;
  s.connected = running_;
  s.accepted = emitted_;
  s.connections = running_ ? 1 : 0;
  return s;
}

void ManualSource::placeTools(const sim::SceneDef& def) {
  const Eigen::Vector3d target = def.camera.target;
  const Eigen::Vector3d toward = (def.camera.eye - def.camera.target).normalized();
  Eigen::Vector3d up = def.camera.up - def.camera.up.dot(toward) * toward;
  up = up.norm() > 1e-9 ? up.normalized() : toward.unitOrthogonal();
  const Eigen::Vector3d right = up.cross(toward);
  volume_ = Eigen::AlignedBox3d(target);
  for (int h = 0; h < sim::kHandCount; ++h) {
    const double side = h == 0 ? -1.0 : 1.0;
    sim::HandInput& in = home_[static_cast<std::size_t>(h)];
    in.instrument = sim::Instrument::Forceps;
    in.tracked = true;
    in.position = target + side * 1.2 * right + 0.6 * toward;
    in.orientation = toolOrientation(side * right + toward, up);
    in.closure = 0.0;
    volume_.extend(in.position);
  }
  const auto rest = def.tissue.model.restPositions();
  for (Eigen::Index i = 0; i < rest.cols(); ++i) volume_.extend(Eigen::Vector3d(rest.col(i)));
  if (def.needle) {
    // the needle where it lies, as far as it reaches from its frame's origin either way
    const sim::suture::SutureDef& needle = def.needle->suture;
    const double reach = needle.needleShape == sim::suture::NeedleShape::Curved ? 2.0 * needle.needleRadius
                                                                               : needle.needleLength;
    const Eigen::Vector3d at = def.needle->pose.translation();
    volume_.extend(at - Eigen::Vector3d::Constant(reach));
    volume_.extend(at + Eigen::Vector3d::Constant(reach));
  }
  volume_.min().array() -= kWorkingMarginMm;
  volume_.max().array() += kWorkingMarginMm;
  frame_.hands = home_;
  held_ = {};
  scissorsInScene_ = def.scissors.has_value();
  if (running_) emitFrame();
}

void ManualSource::setViewBasis(const Eigen::Vector3d& right, const Eigen::Vector3d& up,
                                const Eigen::Vector3d& towardViewer) {
  right_ = right.normalized();
  up_ = up.normalized();
  toward_ = towardViewer.normalized();
}

bool ManualSource::handleKey(int key, Qt::KeyboardModifiers modifiers, bool pressed, bool autoRepeat) {
  const bool fine = modifiers.testFlag(Qt::ShiftModifier);
  const double step = fine ? kFineStepMm : kStepMm;
  const double angle = fine ? kFineStepDeg : kStepDeg;
  if (key == Qt::Key_Space) {
    if (autoRepeat) return true;
    setClosure(pressed ? 1.0 : 0.0);
    return true;
  }
  const bool known = key == Qt::Key_Tab || key == Qt::Key_Backtab || key == Qt::Key_A ||
                     key == Qt::Key_D || key == Qt::Key_W || key == Qt::Key_S || key == Qt::Key_Q ||
                     key == Qt::Key_E || key == Qt::Key_Left || key == Qt::Key_Right ||
                     key == Qt::Key_Up || key == Qt::Key_Down || key == Qt::Key_R ||
                     key == Qt::Key_Z || key == Qt::Key_X || key == Qt::Key_C || key == Qt::Key_V ||
                     key == Qt::Key_T;
  if (!known) return false;
  if (!pressed) return true;  // moves happen on presses and key repeats
  switch (key) {
    case Qt::Key_Tab:
    case Qt::Key_Backtab:
      if (autoRepeat) return true;
      active_ = active_ == sim::Hand::Left ? sim::Hand::Right : sim::Hand::Left;
      Q_EMIT activeHandChanged(active_);
      return true;
    case Qt::Key_T:
      if (!autoRepeat) switchActiveInstrument();
      return true;
    case Qt::Key_A: move(-step * right_); break;
    case Qt::Key_D: move(step * right_); break;
    case Qt::Key_W: move(step * up_); break;
    case Qt::Key_S: move(-step * up_); break;
    case Qt::Key_Q: move(-step * toward_); break;
    case Qt::Key_E: move(step * toward_); break;
    case Qt::Key_Left: turn(up_, angle); break;
    case Qt::Key_Right: turn(up_, -angle); break;
    case Qt::Key_Up: turn(right_, -angle); break;
    case Qt::Key_Down: turn(right_, angle); break;
    case Qt::Key_Z: turnAlongNeedle(-(fine ? kFineArcStepDeg : kArcStepDeg)); break;
    case Qt::Key_X: turnAlongNeedle(fine ? kFineArcStepDeg : kArcStepDeg); break;
    case Qt::Key_C: setClosure(frame_.hand(active_).closure + kClosureStep); break;
    case Qt::Key_V: setClosure(frame_.hand(active_).closure - kClosureStep); break;
    case Qt::Key_R:
      frame_.hands = home_;
      emitFrame();
      break;
    default: break;
  }
  return true;
}

void ManualSource::moveInView(double rightMm, double upMm) { move(rightMm * right_ + upMm * up_); }

void ManualSource::moveInDepth(double towardMm) { move(towardMm * toward_); }

void ManualSource::turnInView(double aboutUpDeg, double aboutRightDeg) {
  sim::HandInput& h = frame_.hand(active_);
  const Eigen::Quaterniond yaw(Eigen::AngleAxisd(aboutUpDeg * std::numbers::pi / 180.0, up_));
  const Eigen::Quaterniond pitch(Eigen::AngleAxisd(aboutRightDeg * std::numbers::pi / 180.0, right_));
  h.orientation = (pitch * yaw * h.orientation).normalized();
  emitFrame();
}

bool ManualSource::turnAlongNeedle(double degrees) {
  const std::optional<HeldNeedleArc>& arc = held_[static_cast<std::size_t>(active_)];
  if (!arc) return false;
  // a rigid turn of the tool (and the needle on its jaws) about the circle's axis through its
  // centre: the needle slides along its own circle
  sim::HandInput& h = frame_.hand(active_);
  const Eigen::Vector3d centre = h.position + h.orientation * arc->centre;
  const Eigen::Quaterniond r(Eigen::AngleAxisd(degrees * std::numbers::pi / 180.0, h.orientation * arc->axis));
  h.position = centre + r * (h.position - centre);
  h.orientation = (r * h.orientation).normalized();
  clampToVolume(h);
  emitFrame();
  return true;
}

void ManualSource::setClosure(double closure) {
  frame_.hand(active_).closure = std::clamp(closure, 0.0, 1.0);
  emitFrame();
}

bool ManualSource::switchActiveInstrument() {
  if (!scissorsInScene_) return false;
  sim::HandInput& hand = frame_.hand(active_);
  switchInstrument(hand);
  held_[static_cast<std::size_t>(active_)].reset();  // a forceps put down lets go of the needle
  Q_EMIT instrumentChanged(active_, hand.instrument);
  emitFrame();
  return true;
}

void ManualSource::setHeldNeedle(sim::Hand hand, const std::optional<HeldNeedleArc>& arc) {
  held_[static_cast<std::size_t>(hand)] = arc;
}

void ManualSource::move(const Eigen::Vector3d& deltaMm) {
  sim::HandInput& h = frame_.hand(active_);
  h.position += deltaMm;
  clampToVolume(h);
  emitFrame();
}

void ManualSource::clampToVolume(sim::HandInput& hand) const {
  hand.position = hand.position.cwiseMax(volume_.min()).cwiseMin(volume_.max());
}

void ManualSource::turn(const Eigen::Vector3d& axis, double degrees) {
  sim::HandInput& h = frame_.hand(active_);
  const Eigen::AngleAxisd r(degrees * std::numbers::pi / 180.0, axis.normalized());
  h.orientation = (Eigen::Quaterniond(r) * h.orientation).normalized();
  emitFrame();
}

void ManualSource::emitFrame() {
  if (!running_) return;
  frame_.time = std::max(frame_.time, static_cast<double>(clock_.nsecsElapsed()) * 1e-9);
  ++emitted_;
  Q_EMIT frameReady(frame_);
}

QStringList ManualSource::keyMapHelp() {
  return {
      tr("Tab — switch hand"),
      tr("T — take up the scissors or the forceps (the jaw keys and buttons close either)"),
      tr("A / D — move left / right"),
      tr("W / S — move up / down"),
      tr("Q / E — move away / toward you"),
      tr("← / → — turn the tool"),
      tr("↑ / ↓ — tilt the tool"),
      tr("Z / X — turn the held needle back / forward along its curve"),
      tr("C / V — close / open the jaws a step"),
      tr("Space (hold) — close the jaws"),
      tr("Shift — fine steps"),
      tr("R — reset the tools"),
      tr("Left drag — move the tool in the view plane; wheel — move it in depth"),
      tr("Ctrl + left drag or Ctrl + wheel — turn the held needle along its curve"),
      tr("Ctrl + left drag without a needle — turn the tool"),
      tr("Right drag down / up — close / open the jaws; right click — close or open them"),
      tr("Middle drag or Shift + left drag — orbit; Shift + middle drag — pan"),
      tr("Shift + wheel — zoom; Alt + wheel — focus"),
      tr("Home — microscope view; 1 / 2 / 3 — top / oblique / side view"),
      tr("F1 — show or hide this help"),
  };
}

}  // namespace microsim::tracking
