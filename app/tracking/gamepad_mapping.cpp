#include "tracking/gamepad_mapping.h"

#include <algorithm>

namespace microsim::tracking {

RateCommand gamepadCommand(const GamepadState& state, const GamepadScale& scale) {
  const auto stick = [&scale](double v) { return pastDeadZone(v, scale.deadZone); };
  const auto pair = [](bool positive, bool negative) { return (positive ? 1.0 : 0.0) - (negative ? 1.0 : 0.0); };
  RateCommand command;
  // SDL's y grows downward: pushing a stick up is negative
  command.translation = {stick(state.leftX), stick(-state.leftY), stick(state.rightY)};
  command.rotation = {pair(state.dpadDown, state.dpadUp), stick(-state.rightX),
                      pair(state.dpadLeft, state.dpadRight)};
  return command;
}

std::array<double, sim::kHandCount> gamepadClosures(const GamepadState& state) {
  return {std::clamp(state.leftTrigger, 0.0, 1.0), std::clamp(state.rightTrigger, 0.0, 1.0)};
}

double gamepadAxis(int raw) { return std::clamp(raw / 32767.0, -1.0, 1.0); }

}  // namespace microsim::tracking
