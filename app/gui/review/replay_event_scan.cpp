#include "gui/review/replay_event_scan.h"

#include "microsim/sim/scene/scene.h"

#include <QMetaObject>

#include <pthread.h>

#include <utility>

namespace microsim::gui {

ReplayEventScan::ReplayEventScan(QObject* parent) : QObject(parent) {}

ReplayEventScan::~ReplayEventScan() { cancel(); }

void ReplayEventScan::cancel() {
  cancel_ = true;
  if (thread_.joinable()) thread_.join();
  cancel_ = false;
}

void ReplayEventScan::start(const sim::SceneDef& def, std::vector<sim::InputFrame> frames) {
  cancel();
  done_ = false;
  events_.clear();
  const int generation = ++generation_;
  thread_ = std::thread([this, def, frames = std::move(frames), generation] {
    pthread_setname_np(pthread_self(), "replay scan");
    sim::Scene scene(def, sim::StepMode::Deterministic);
    for (const sim::InputFrame& f : frames) {
      if (cancel_) return;
      scene.step(f);
    }
    // delivered on the GUI thread; dropped with this object, and ignored once a newer scan began
    QMetaObject::invokeMethod(
        this,
        [this, generation, events = scene.events()]() mutable {
          if (generation != generation_) return;
          events_ = std::move(events);
          done_ = true;
          Q_EMIT finished();
        },
        Qt::QueuedConnection);
  });
}

}  // namespace microsim::gui
