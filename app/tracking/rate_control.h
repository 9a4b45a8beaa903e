#pragma once
// Rate control of a tool: how a 6-DoF device that reports deflections (a 3D mouse's cap, a
// game controller's sticks) moves the active forceps. A deflection is not a position but a
// velocity: the tool moves while the device is pushed and stays where it is when it is let go.
//
// A RateCommand is the device's deflection, each component in −1..1, in the *view's* axes
// (right, up, toward the viewer), so that pushing the cap or a stick to the right moves the
// tool to the right on screen whatever the microscope's orientation. Over dt seconds:
//
//   p' = p + v_max · dt · (t_r·right + t_u·up + t_v·toward)                      (mm)
//   ω  = r_r·right + r_u·up + r_v·toward,  q' = R(ω̂, |ω| · w_max · dt) · q        (about the tip)
//
// with v_max and w_max the limits below. They are scaled to a ~1 mm vessel: at full deflection
// the tip crosses the vessel in half a second and turns a quarter turn in 1.5 s, so the fine
// placement of a bite (a few hundredths of a millimetre) is a light push held briefly.

#include "microsim/sim/scene/input_frame.h"
#include "microsim/sim/scene/render_snapshot.h"

#include <Eigen/Core>

#include <optional>

namespace microsim::tracking {

/// The view's unit axes in the scene frame (right-handed: right × up = toward).
struct ViewAxes {
  Eigen::Vector3d right = Eigen::Vector3d::UnitX();
  Eigen::Vector3d up = Eigen::Vector3d::UnitY();
  Eigen::Vector3d toward = Eigen::Vector3d::UnitZ();  ///< from the scene toward the viewer
};

/// A device's deflection, components in −1..1 along / about the view's axes.
struct RateCommand {
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();  ///< right, up, toward the viewer
  Eigen::Vector3d rotation = Eigen::Vector3d::Zero();     ///< about right, up, toward (right-hand rule)

  bool isZero() const { return translation.isZero(0.0) && rotation.isZero(0.0); }
};

struct RateLimits {
  double mmPerS = 2.0;    ///< mm/s of the tip at full deflection
  double degPerS = 60.0;  ///< °/s of the tool at full deflection
};

/// The hand after `dtS` seconds at `command` (equations above); the closure, instrument and
/// tracking flag are kept. Components outside −1..1 are clamped.
sim::HandInput applyRate(const sim::HandInput& hand, const RateCommand& command, const ViewAxes& view,
                         const RateLimits& limits, double dtS);

/// A deflection past a dead zone, rescaled so that the response starts at 0 at the zone's edge
/// and reaches ±1 at full deflection: sign(x) · (|x| − dead) / (1 − dead), 0 inside the zone.
/// `value` and `dead` in device-normalised units (full deflection = 1).
double pastDeadZone(double value, double dead);

/// The tools as a snapshot shows them, as the frame that would put them there (tracked where
/// the scene has the tool, with the instrument the hand holds and its closure: the scissors'
/// while it holds them); nullopt when the scene has no forceps.
std::optional<sim::InputFrame> toolsShown(const sim::RenderSnapshot& snapshot);

}  // namespace microsim::tracking
