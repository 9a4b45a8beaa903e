#pragma once
// A game controller for tests that is no stub: SDL's virtual joystick (SDL ≥ 2.0.14), plugged
// in through the real library with the standard controller layout, so GamepadSource finds it,
// opens it and reads it exactly as it reads a USB pad. Needs no display: only SDL's
// game-controller part is started.
#include <SDL.h>

#include <cmath>
#include <string>

namespace microsim::testing {

class VirtualGamepad {
 public:
  static constexpr const char* kName = "microsim virtual pad";

  VirtualGamepad() {
    SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
    if (SDL_InitSubSystem(SDL_INIT_GAMECONTROLLER) != 0) return;
    started_ = true;
    controllersBefore_ = SDL_NumJoysticks();
    SDL_VirtualJoystickDesc desc;
    SDL_zero(desc);
    desc.version = SDL_VIRTUAL_JOYSTICK_DESC_VERSION;
    desc.type = SDL_JOYSTICK_TYPE_GAMECONTROLLER;
    desc.naxes = SDL_CONTROLLER_AXIS_MAX;
    desc.nbuttons = SDL_CONTROLLER_BUTTON_MAX;
    desc.name = kName;
    index_ = SDL_JoystickAttachVirtualEx(&desc);
    if (index_ >= 0) joystick_ = SDL_JoystickOpen(index_);
  }
  ~VirtualGamepad() {
    unplug();
    if (started_) SDL_QuitSubSystem(SDL_INIT_GAMECONTROLLER);
  }
  VirtualGamepad(const VirtualGamepad&) = delete;
  VirtualGamepad& operator=(const VirtualGamepad&) = delete;

  bool pluggedIn() const { return joystick_ != nullptr; }
  /// Controllers already there (a real pad on the machine would be found first).
  int controllersBefore() const { return controllersBefore_; }
  std::string error() const { return SDL_GetError(); }

  /// A stick's axis in SDL's units: −32768..32767, y positive down.
  void setAxis(SDL_GameControllerAxis axis, Sint16 value) {
    SDL_JoystickSetVirtualAxis(joystick_, axis, value);
  }
  /// A trigger pulled by `pulled` (0..1). The virtual device's trigger is a full-range axis
  /// resting at −32768, which SDL's controller layer reads as 0..32767, as for a real pad.
  void setTrigger(SDL_GameControllerAxis axis, double pulled) {
    SDL_JoystickSetVirtualAxis(joystick_, axis, static_cast<Sint16>(std::lround(-32768.0 + pulled * 65535.0)));
  }
  void setButton(SDL_GameControllerButton button, bool pressed) {
    SDL_JoystickSetVirtualButton(joystick_, button, pressed ? 1 : 0);
  }
  void unplug() {
    if (joystick_ != nullptr) SDL_JoystickClose(joystick_);
    joystick_ = nullptr;
    if (index_ >= 0) SDL_JoystickDetachVirtual(index_);
    index_ = -1;
  }

 private:
  bool started_ = false;
  int controllersBefore_ = 0;
  int index_ = -1;
  SDL_Joystick* joystick_ = nullptr;
};

}  // namespace microsim::testing
