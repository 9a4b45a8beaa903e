#include "tracking/rate_tool_source.h"

#include "tracking/instrument_switch.h"

#include <algorithm>

namespace microsim::tracking {

RateToolSource::RateToolSource(QObject* parent) : TrackerSource(parent) {
  for (sim::HandInput& hand : frame_.hands) hand.tracked = true;
}

TrackerStatus RateToolSource::status() const {
  TrackerStatus s;
  s.connected = running_;
  s.accepted = emitted_;
  s.connections = connections_;
  s.lastError = lastError_;
  return s;
}

void RateToolSource::setTools(const sim::InputFrame& frame) {
  const double time = frame_.time;
  frame_ = frame;
  frame_.time = time;
}

void RateToolSource::linkUp() {
  clock_.start();
  running_ = true;
  moving_ = false;
  ++connections_;
  lastError_.clear();
  Q_EMIT connectedChanged(true);
}

void RateToolSource::linkClosed() {
  if (!running_) return;
  running_ = false;
  Q_EMIT connectedChanged(false);
}

void RateToolSource::linkFailed(const QString& error) {
  lastError_ = error;
  if (running_) {
    // the tools stay where they are until the device is back
    for (sim::HandInput& hand : frame_.hands) hand.tracked = false;
    emitFrame();
    for (sim::HandInput& hand : frame_.hands) hand.tracked = true;
    running_ = false;
    Q_EMIT connectedChanged(false);
  }
  Q_EMIT linkDown();
}

void RateToolSource::drive(const RateCommand& command, double dtS) {
  if (!running_) return;
  if (command.isZero()) {
    moving_ = false;
    return;
  }
  if (!moving_) takeToolsShown();
  moving_ = true;
  const ViewAxes view = view_ ? view_() : ViewAxes{};
  sim::HandInput& hand = frame_.hand(active_);
  hand = applyRate(hand, command, view, limits_, std::max(dtS, 0.0));
  if (volume_)
    if (const std::optional<Eigen::AlignedBox3d> box = volume_())
      hand.position = hand.position.cwiseMax(box->min()).cwiseMin(box->max());
  emitFrame();
}

void RateToolSource::setClosure(sim::Hand hand, double closure) {
  if (!running_) return;
  const double c = std::clamp(closure, 0.0, 1.0);
  if (frame_.hand(hand).closure == c) return;
  if (!moving_) takeToolsShown();
  frame_.hand(hand).closure = c;
  emitFrame();
}

void RateToolSource::selectHand(sim::Hand hand) {
  if (hand == active_) return;
  active_ = hand;
  moving_ = false;  // the other tool may have been moved meanwhile: take it as shown
  Q_EMIT activeHandChanged(active_);
}

void RateToolSource::switchHand() {
  selectHand(active_ == sim::Hand::Left ? sim::Hand::Right : sim::Hand::Left);
}

void RateToolSource::switchActiveInstrument() {
  if (!running_ || (scissors_ && !scissors_())) return;
  if (!moving_) takeToolsShown();
  switchInstrument(frame_.hand(active_));
  emitFrame();
}

void RateToolSource::takeToolsShown() {
  if (!anchor_) return;
  const std::optional<sim::InputFrame> shown = anchor_();
  if (shown) setTools(*shown);
}

void RateToolSource::emitFrame() {
  if (!running_) return;
  frame_.time = std::max(frame_.time, static_cast<double>(clock_.nsecsElapsed()) * 1e-9);
  ++emitted_;
  Q_EMIT frameReady(frame_);
}

}  // namespace microsim::tracking
