#pragma once
// What a 3D mouse's events mean for the tools (pure: tested without a device or a daemon).
//
// spacenavd reports the cap's deflection as six integers in its own left-handed frame
// (x right, y up, z into the screen; rotations about those axes), about ±350 at full
// deflection on a SpaceNavigator, and the time since the previous motion event. In the
// view's right-handed frame (z toward the viewer) that is
//
//   translation = (x, y, −z) / full,   rotation = (−rx, −ry, rz) / full
//
// (a reflection of z flips the sense of the rotations about x and y: libspnav's own cube
// example converts the same way), each past a dead zone (rate_control.h's pastDeadZone).
// The cap moves the active tool: push it to move, twist or tilt it to turn the tool about
// its tip. Button 0 (the left one) held closes the active jaws (or scissors); button 1 (the
// right one) switches the active hand; button 2 (on the larger models) swaps the active
// hand's forceps for the scissors; further buttons do nothing. A two-button SpaceNavigator
// swaps instruments with the keyboard's T: the device carries on with whatever the scene
// shows in the hand (rate_tool_source.h's anchor).

#include "tracking/rate_control.h"

namespace microsim::tracking {

/// One motion event as spacenavd sends it.
struct SpacenavMotion {
  int x = 0, y = 0, z = 0;     ///< translation deflection, device counts
  int rx = 0, ry = 0, rz = 0;  ///< rotation deflection, device counts
  unsigned periodMs = 0;       ///< ms since the previous motion event
};

struct SpacenavScale {
  double fullScale = 350.0;  ///< device counts at full deflection
  double deadZone = 0.04;    ///< of full deflection, ignored (the cap never rests at exactly 0)
  double maxStepS = 0.05;    ///< longest interval integrated at once (the first event after a rest
                             ///< reports the whole rest as its period)
};

enum class SpacenavButtonAction { None, HoldJaws, SwitchHand, SwitchInstrument };

/// The deflection of a motion event in the view's axes (equation above).
RateCommand spacenavCommand(const SpacenavMotion& motion, const SpacenavScale& scale = {});
/// The seconds a motion event moves the tool for: its period, at most maxStepS.
double spacenavStep(const SpacenavMotion& motion, const SpacenavScale& scale = {});
SpacenavButtonAction spacenavButtonAction(int button);

}  // namespace microsim::tracking
