#pragma once
// Tool control without trackers: the keyboard (and the viewport's mouse) drive the two hands'
// tools, each the forceps or the microscissors.
// Key map (view-relative: "right", "up" and "depth" follow the microscope's current view):
//   Tab            switch the active hand (left ↔ right)
//   T              the active hand puts its forceps down and takes up the scissors, or back
//                  (instrument_switch.h; only where the scene declares scissors)
//   A / D          move the active tip left / right        W / S   up / down
//   Q / E          move the active tip away from / toward the viewer (depth)
//   ← / →          turn the active tool about the view's up axis
//   ↑ / ↓          tilt the active tool about the view's right axis
//   Z / X          turn a held needle back / forward along its own curve
//   C / V          close / open the active jaws (or blades) a step
//   Space (held)   close the active jaws (or blades); released, they open
//   R              put both tools back at their start poses
//   Shift + any move or turn: fine steps
// Steps: kStepMm (kFineStepMm with Shift) per press or key repeat; kStepDeg / kFineStepDeg per
// turn, kArcStepDeg / kFineArcStepDeg along the needle, kClosureStep per jaw step. The
// viewport drives the same moves from the mouse (moveInView, moveInDepth, turnInView,
// turnAlongNeedle, setClosure) and shows the key and mouse map on F1 (keyMapHelp()).
//
// Along the needle. While the active forceps holds a curved needle (the viewport tells it
// which, and where the needle's circle lies on the jaws: held_needle_arc.h), Z / X turn the
// tool about the axis of that circle through its centre: the wrist turn that drives a needle
// through a wall along its curve. Without a held needle they do nothing.
//
// Working volume. Tips stay in a box around what the scene holds (the tissue's rest nodes,
// the needle where it lies, the tools' start poses), kWorkingMarginMm beyond it on every side
// (placeTools sets it), so a tool cannot wander off where nothing is.
//
// Every change emits frameReady with both hands (tracked, each with its instrument) and the time in s since
// start(), never earlier than the previous frame's. Nothing is emitted before start() or after
// stop(). Poses are in the scene frame already (no calibration applies to this source).

#include "tracking/held_needle_arc.h"
#include "tracking/tracker_source.h"

#include "microsim/sim/scene/scene_def.h"

#include <QElapsedTimer>
#include <QStringList>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <optional>

namespace microsim::tracking {

class ManualSource : public TrackerSource {
  Q_OBJECT

 public:
  static constexpr double kStepMm = 0.05;       ///< mm per key press
  static constexpr double kFineStepMm = 0.01;   ///< mm per key press with Shift
  static constexpr double kStepDeg = 5.0;       ///< degrees per key press
  static constexpr double kFineStepDeg = 1.0;   ///< degrees per key press with Shift
  static constexpr double kArcStepDeg = 2.0;    ///< degrees along a held needle per key press
  static constexpr double kFineArcStepDeg = 0.5;  ///< the same with Shift
  static constexpr double kClosureStep = 0.1;   ///< jaw closure (0 open .. 1 closed) per key press
  static constexpr double kWorkingMarginMm = 1.5;  ///< the working volume beyond the scene's things

  explicit ManualSource(QObject* parent = nullptr);

  void start() override;
  void stop() override;
  TrackerStatus status() const override;

  /// Start poses beside the scene's camera target (each tool 1.2 mm to its side and 0.6 mm
  /// toward the viewer, jaws open, pointing in at the target); used on R too. Sets the working
  /// volume around the scene (header essay), forgets any held needle and notes whether the
  /// scene has scissors to take up.
  void placeTools(const sim::SceneDef& def);
  /// The box the tips are kept in (scene frame, mm).
  const Eigen::AlignedBox3d& workingVolume() const { return volume_; }
  /// The view's unit axes in the scene frame (the viewport keeps them current).
  void setViewBasis(const Eigen::Vector3d& right, const Eigen::Vector3d& up,
                    const Eigen::Vector3d& towardViewer);
  /// One key event; returns true when the key belongs to the map (the caller accepts it).
  bool handleKey(int key, Qt::KeyboardModifiers modifiers, bool pressed, bool autoRepeat);
  /// Moves the active tip in the view plane (mm along the view's right and up axes).
  void moveInView(double rightMm, double upMm);
  /// Moves the active tip along the view axis (mm, positive toward the viewer).
  void moveInDepth(double towardMm);
  /// Turns the active tool about its tip: about the view's up axis, then its right axis
  /// (degrees, right hand).
  void turnInView(double aboutUpDeg, double aboutRightDeg);
  /// Turns the active tool along the needle it holds (degrees, positive: tip first); false,
  /// and nothing moves, when it holds none.
  bool turnAlongNeedle(double degrees);
  /// Sets the active jaws' closure (clamped to 0 open .. 1 closed).
  void setClosure(double closure);
  /// The active hand swaps its forceps for the scissors or back (T); false, and nothing
  /// changes, when the scene declares no scissors.
  bool switchActiveInstrument();
  /// What `hand` holds of a needle, in its tool frame (null: no needle); the viewport keeps it
  /// current from the drawn snapshot.
  void setHeldNeedle(sim::Hand hand, const std::optional<HeldNeedleArc>& arc);
  const std::optional<HeldNeedleArc>& heldNeedle(sim::Hand hand) const {
    return held_[static_cast<std::size_t>(hand)];
  }

  sim::Hand activeHand() const { return active_; }
  /// The frame as it stands (the last one emitted, or the next if not started).
  const sim::InputFrame& current() const { return frame_; }
  /// The key map as translated lines: "keys — action".
  static QStringList keyMapHelp();

 Q_SIGNALS:
  void activeHandChanged(microsim::sim::Hand hand);
  void instrumentChanged(microsim::sim::Hand hand, microsim::sim::Instrument instrument);

 private:
  void emitFrame();
  void move(const Eigen::Vector3d& deltaMm);
  void turn(const Eigen::Vector3d& axis, double degrees);
  void clampToVolume(sim::HandInput& hand) const;

  sim::InputFrame frame_;
  std::array<sim::HandInput, sim::kHandCount> home_{};
  sim::Hand active_ = sim::Hand::Right;
  Eigen::Vector3d right_ = Eigen::Vector3d::UnitX();
  Eigen::Vector3d up_ = Eigen::Vector3d::UnitY();
  Eigen::Vector3d toward_ = Eigen::Vector3d::UnitZ();
  Eigen::AlignedBox3d volume_;
  std::array<std::optional<HeldNeedleArc>, sim::kHandCount> held_{};
  bool scissorsInScene_ = false;
  QElapsedTimer clock_;
  bool running_ = false;
  std::uint64_t emitted_ = 0;
};

}  // namespace microsim::tracking
