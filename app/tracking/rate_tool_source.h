#pragma once
// What the 6-DoF devices have in common (the 3D mouse, spacenav_source.h; the game
// controller, gamepad_source.h): they report deflections, not poses, so they move the tools
// they are given at a rate (rate_control.h) rather than placing them.
//
// Where the tools are: a device takes the tools where the scene shows them each time it
// starts to move after a rest (setToolAnchor: the viewport's latest snapshot in the app), so
// it carries on from wherever the keyboard, the mouse or another device left them instead of
// making them jump; while it moves, it integrates its own frame. Without an anchor (or while
// the anchor has no scene) it moves the frame set by setTools.
// Which way is right: the view's axes are read from setViewAxesProvider at every motion (the
// microscope may have been turned since).
//
// Frames are in the scene frame (no calibration applies), stamped in s since start() and
// never earlier than the previous one; both hands are in every frame. Nothing is emitted
// before start(), after stop() or while the device is at rest with nothing changed, so a
// device lying idle does not fight the keyboard.

#include "tracking/rate_control.h"
#include "tracking/tracker_source.h"

#include <QElapsedTimer>

#include <Eigen/Geometry>

#include <functional>
#include <optional>

namespace microsim::tracking {

class RateToolSource : public TrackerSource {
  Q_OBJECT

 public:
  using ToolAnchor = std::function<std::optional<sim::InputFrame>()>;
  using ViewAxesProvider = std::function<ViewAxes()>;
  /// The box the tool tips are kept in (scene frame, mm); none: no scene, no limit.
  using WorkingVolumeProvider = std::function<std::optional<Eigen::AlignedBox3d>()>;
  /// Whether the scene declares scissors for a hand to take up.
  using ScissorsInScene = std::function<bool()>;

  explicit RateToolSource(QObject* parent = nullptr);

  TrackerStatus status() const override;

  /// Where the tools are when a motion starts (null: the source's own frame).
  void setToolAnchor(ToolAnchor anchor) { anchor_ = std::move(anchor); }
  /// The view's axes (null: the scene's x, y, z).
  void setViewAxesProvider(ViewAxesProvider provider) { view_ = std::move(provider); }
  /// The working volume a moved tip is kept in (the keyboard's: ManualSource::workingVolume),
  /// so a device cannot take a tool off where nothing is (null: no limit).
  void setWorkingVolumeProvider(WorkingVolumeProvider provider) { volume_ = std::move(provider); }
  /// Whether a swap of instruments may take up the scissors (null: it may); without them the
  /// swap does nothing, as the keyboard's T (manual_source.h).
  void setScissorsInScene(ScissorsInScene scissors) { scissors_ = std::move(scissors); }
  /// The frame the next motion starts from when there is no anchor.
  void setTools(const sim::InputFrame& frame);
  void setLimits(const RateLimits& limits) { limits_ = limits; }
  const RateLimits& limits() const { return limits_; }

  sim::Hand activeHand() const { return active_; }
  /// The last frame emitted (or the one the next motion starts from).
  const sim::InputFrame& current() const { return frame_; }

 Q_SIGNALS:
  void activeHandChanged(microsim::sim::Hand hand);

 protected:
  /// The device is open: frames may flow.
  void linkUp();
  /// The device is closed by stop(): no frame after this.
  void linkClosed();
  /// The device failed or went away: `error` is kept as status().lastError, the hands are
  /// marked untracked (the tools stay where they are) and linkDown is emitted.
  void linkFailed(const QString& error);
  bool running() const { return running_; }

  /// Moves the active tool for `dtS` seconds at `command`; a zero command ends the motion.
  void drive(const RateCommand& command, double dtS);
  /// Sets a hand's jaws (0 open .. 1 closed); emits when it changed.
  void setClosure(sim::Hand hand, double closure);
  void selectHand(sim::Hand hand);
  void switchHand();
  /// The active hand swaps its forceps for the scissors or back (instrument_switch.h).
  void switchActiveInstrument();

 private:
  void takeToolsShown();
  void emitFrame();

  ToolAnchor anchor_;
  ViewAxesProvider view_;
  WorkingVolumeProvider volume_;
  ScissorsInScene scissors_;
  RateLimits limits_;
  sim::InputFrame frame_;
  sim::Hand active_ = sim::Hand::Right;
  bool moving_ = false;
  bool running_ = false;
  QElapsedTimer clock_;
  std::uint64_t emitted_ = 0;
  std::uint64_t connections_ = 0;
  QString lastError_;
};

}  // namespace microsim::tracking
