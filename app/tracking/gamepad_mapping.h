#pragma once
// What a game controller's sticks, triggers and buttons mean for the tools (pure: tested
// without a controller). The names are SDL's standard controller layout (an Xbox-style pad;
// SDL maps PlayStation, Switch and most other pads onto it).
//
//   left stick          move the active tip in the view plane (right, up)
//   right stick         up / down: depth (up = away from the viewer); left / right: turn the
//                       tool about the view's up axis
//   D-pad up / down     tilt the tool about the view's right axis
//   D-pad left / right  roll the tool about the axis toward the viewer
//   left / right trigger  close the left / right jaws, gradually (half pulled = half closed)
//   left / right shoulder make the left / right hand the active one
//   Y (the top face button)  the active hand takes up the scissors, or the forceps again
//
// Sticks report −1..1 (SDL: −32768..32767, y positive *down*), triggers 0..1; a stick is read
// past a dead zone (rate_control.h's pastDeadZone) since a released stick rarely rests at 0.

#include "tracking/rate_control.h"

#include "microsim/sim/scene/input_frame.h"

#include <array>

namespace microsim::tracking {

/// One reading of the controller, normalised.
struct GamepadState {
  double leftX = 0.0, leftY = 0.0;    ///< −1..1, y positive down (SDL's convention)
  double rightX = 0.0, rightY = 0.0;  ///< −1..1, y positive down
  double leftTrigger = 0.0, rightTrigger = 0.0;  ///< 0..1
  bool leftShoulder = false, rightShoulder = false;
  bool y = false;  ///< the top face button (Xbox Y, PlayStation △, Switch X)
  bool dpadUp = false, dpadDown = false, dpadLeft = false, dpadRight = false;
};

struct GamepadScale {
  double deadZone = 0.15;  ///< of full stick deflection
};

/// The deflection of the sticks and the D-pad in the view's axes (table above).
RateCommand gamepadCommand(const GamepadState& state, const GamepadScale& scale = {});
/// Each hand's jaws from its trigger: [0] left, [1] right, 0..1.
std::array<double, sim::kHandCount> gamepadClosures(const GamepadState& state);

/// SDL's raw axis value (−32768..32767) as −1..1.
double gamepadAxis(int raw);

}  // namespace microsim::tracking
