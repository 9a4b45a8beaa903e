#pragma once
// Tool control without trackers: the keyboard (and the viewport's mouse) drive the two forceps.
// Key map (view-relative: "right", "up" and "depth" follow the microscope's current view):
//   Tab            switch the active hand (left ↔ right)
//   A / D          move the active tip left / right        W / S   up / down
//   Q / E          move the active tip away from / toward the viewer (depth)
//   ← / →          turn the active tool about the view's up axis
//   ↑ / ↓          tilt the active tool about the view's right axis
//   Space (held)   close the active jaws; released, they open
//   R              put both tools back at their start poses
//   Shift + any move or turn: fine steps
// Steps: kStepMm (kFineStepMm with Shift) per press or key repeat; kStepDeg / kFineStepDeg per
// turn. The viewport also moves the active tip by a right-drag in the view plane (moveInView)
// and shows this map on F1 (keyMapHelp()).
//
// Every change emits frameReady with both hands (tracked, Forceps) and the time in s since
// start(), never earlier than the previous frame's. Nothing is emitted before start() or after
// stop(). Poses are in the scene frame already (no calibration applies to this source).

#include "tracking/tracker_source.h"

#include "microsim/sim/scene/scene_def.h"

#include <QElapsedTimer>
#include <QStringList>

#include <Eigen/Core>

#include <array>

namespace microsim::tracking {

class ManualSource : public TrackerSource {
  Q_OBJECT

 public:
  static constexpr double kStepMm = 0.05;       ///< mm per key press
  static constexpr double kFineStepMm = 0.01;   ///< mm per key press with Shift
  static constexpr double kStepDeg = 5.0;       ///< degrees per key press
  static constexpr double kFineStepDeg = 1.0;   ///< degrees per key press with Shift

  explicit ManualSource(QObject* parent = nullptr);

  void start() override;
  void stop() override;
  TrackerStatus status() const override;

  /// Start poses beside the scene's camera target (each tool 1.2 mm to its side and 0.6 mm
  /// toward the viewer, jaws open, pointing in at the target); used on R too.
  void placeTools(const sim::SceneDef& def);
  /// The view's unit axes in the scene frame (the viewport keeps them current).
  void setViewBasis(const Eigen::Vector3d& right, const Eigen::Vector3d& up,
                    const Eigen::Vector3d& towardViewer);
  /// One key event; returns true when the key belongs to the map (the caller accepts it).
  bool handleKey(int key, Qt::KeyboardModifiers modifiers, bool pressed, bool autoRepeat);
  /// Moves the active tip in the view plane (mm along the view's right and up axes).
  void moveInView(double rightMm, double upMm);

  sim::Hand activeHand() const { return active_; }
  /// The frame as it stands (the last one emitted, or the next if not started).
  const sim::InputFrame& current() const { return frame_; }
  /// The key map as translated lines: "keys — action".
  static QStringList keyMapHelp();

 Q_SIGNALS:
  void activeHandChanged(microsim::sim::Hand hand);

 private:
  void emitFrame();
  void move(const Eigen::Vector3d& deltaMm);
  void turn(const Eigen::Vector3d& axis, double degrees);

  sim::InputFrame frame_;
  std::array<sim::HandInput, sim::kHandCount> home_{};
  sim::Hand active_ = sim::Hand::Right;
  Eigen::Vector3d right_ = Eigen::Vector3d::UnitX();
  Eigen::Vector3d up_ = Eigen::Vector3d::UnitY();
  Eigen::Vector3d toward_ = Eigen::Vector3d::UnitZ();
  QElapsedTimer clock_;
  bool running_ = false;
  std::uint64_t emitted_ = 0;
};

}  // namespace microsim::tracking
