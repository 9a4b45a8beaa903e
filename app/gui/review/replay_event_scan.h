#pragma once
// Reads what happens in a recording before it is played: steps the whole recording through a
// scene of its own on a thread of its own (Deterministic, so the events are those the player
// will show, at the same steps) and hands the scene's events back on the GUI thread.
//
// The replay timeline needs every event up front, and the player's scene is at the frame the
// instructor looks at; sim::Scene cannot be copied, so the scan builds a second one. It does
// not touch the player's runner. A new start() or the destructor stops the scan in progress
// after its current step and joins its thread; only the newest scan's result is delivered.

#include "microsim/sim/scene/input_frame.h"
#include "microsim/sim/scene/scene_def.h"
#include "microsim/sim/scene/scene_events.h"

#include <QObject>

#include <atomic>
#include <thread>
#include <vector>

namespace microsim::gui {

class ReplayEventScan : public QObject {
  Q_OBJECT

 public:
  explicit ReplayEventScan(QObject* parent = nullptr);
  ~ReplayEventScan() override;

  /// Scans `frames` on a copy of `def`, stopping any scan in progress.
  void start(const sim::SceneDef& def, std::vector<sim::InputFrame> frames);
  void cancel();
  bool isRunning() const { return thread_.joinable() && !done_; }
  /// The events of the last finished scan.
  const std::vector<sim::SceneEvent>& events() const { return events_; }

 Q_SIGNALS:
  /// The scan reached the end; events() holds what it found.
  void finished();

 private:
  std::thread thread_;
  std::atomic<bool> cancel_{false};
  bool done_ = false;
  int generation_ = 0;
  std::vector<sim::SceneEvent> events_;
};

}  // namespace microsim::gui
