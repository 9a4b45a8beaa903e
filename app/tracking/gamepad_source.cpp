#include "tracking/gamepad_source.h"

#include <SDL.h>

#include <algorithm>

namespace microsim::tracking {

namespace {

GamepadState readGamepad(SDL_GameController* pad) {
  const auto axis = [pad](SDL_GameControllerAxis a) { return gamepadAxis(SDL_GameControllerGetAxis(pad, a)); };
  const auto button = [pad](SDL_GameControllerButton b) { return SDL_GameControllerGetButton(pad, b) != 0; };
  GamepadState s;
  s.leftX = axis(SDL_CONTROLLER_AXIS_LEFTX);
  s.leftY = axis(SDL_CONTROLLER_AXIS_LEFTY);
  s.rightX = axis(SDL_CONTROLLER_AXIS_RIGHTX);
  s.rightY = axis(SDL_CONTROLLER_AXIS_RIGHTY);
  s.leftTrigger = std::max(0.0, axis(SDL_CONTROLLER_AXIS_TRIGGERLEFT));
  s.rightTrigger = std::max(0.0, axis(SDL_CONTROLLER_AXIS_TRIGGERRIGHT));
  s.leftShoulder = button(SDL_CONTROLLER_BUTTON_LEFTSHOULDER);
  s.rightShoulder = button(SDL_CONTROLLER_BUTTON_RIGHTSHOULDER);
  s.y = button(SDL_CONTROLLER_BUTTON_Y);
  s.dpadUp = button(SDL_CONTROLLER_BUTTON_DPAD_UP);
  s.dpadDown = button(SDL_CONTROLLER_BUTTON_DPAD_DOWN);
  s.dpadLeft = button(SDL_CONTROLLER_BUTTON_DPAD_LEFT);
  s.dpadRight = button(SDL_CONTROLLER_BUTTON_DPAD_RIGHT);
  return s;
}

}  // namespace

struct GamepadSource::OpenController {
  SDL_GameController* pad = nullptr;
};

GamepadSource::GamepadSource(GamepadSourceOptions options, QObject* parent)
    : RateToolSource(parent), options_(options) {
  connect(&timer_, &QTimer::timeout, this, &GamepadSource::poll);
}

GamepadSource::~GamepadSource() { closeController(); }

void GamepadSource::start() {
  if (running()) return;
  SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
  if (SDL_InitSubSystem(SDL_INIT_GAMECONTROLLER) != 0) {
    linkFailed(tr("The game controller cannot be read: SDL did not start (%1).")
                   .arg(QString::fromUtf8(SDL_GetError())));
    return;
  }
  SDL_GameController* pad = nullptr;
  for (int i = 0; i < SDL_NumJoysticks() && pad == nullptr; ++i)
    if (SDL_IsGameController(i) == SDL_TRUE) pad = SDL_GameControllerOpen(i);
  if (pad == nullptr) {
    SDL_QuitSubSystem(SDL_INIT_GAMECONTROLLER);
    linkFailed(tr("No game controller found: connect one (USB or Bluetooth) and try again."));
    return;
  }
  controller_ = std::make_unique<OpenController>(OpenController{pad});
  name_ = QString::fromUtf8(SDL_GameControllerName(pad));
  previous_ = {};
  linkUp();
  sincePoll_.start();
  if (options_.pollIntervalMs > 0) timer_.start(options_.pollIntervalMs);
}

void GamepadSource::stop() {
  closeController();
  linkClosed();
}

void GamepadSource::closeController() {
  timer_.stop();
  if (!controller_) return;
  SDL_GameControllerClose(controller_->pad);
  controller_.reset();
  SDL_QuitSubSystem(SDL_INIT_GAMECONTROLLER);
}

void GamepadSource::poll() {
  // a stalled event loop must not turn into one long jump
  const double dt = std::min(static_cast<double>(sincePoll_.restart()) * 1e-3, 0.1);
  advance(dt);
}

void GamepadSource::advance(double dtS) {
  if (!running() || !controller_) return;
  SDL_GameControllerUpdate();
  if (SDL_GameControllerGetAttached(controller_->pad) != SDL_TRUE) {
    const QString name = name_;
    closeController();
    linkFailed(tr("The game controller %1 was disconnected.").arg(name));
    return;
  }
  const GamepadState state = readGamepad(controller_->pad);

  // a shoulder chooses the hand as it is pressed
  if (state.leftShoulder && !previous_.leftShoulder) selectHand(sim::Hand::Left);
  if (state.rightShoulder && !previous_.rightShoulder) selectHand(sim::Hand::Right);
  // Y swaps the active hand's instrument as it is pressed
  if (state.y && !previous_.y) switchActiveInstrument();

  // a trigger sets its jaws when it moves, so jaws another source closed stay closed while
  // the trigger rests
  const std::array<double, sim::kHandCount> closures = gamepadClosures(state);
  const std::array<double, sim::kHandCount> before = gamepadClosures(previous_);
  for (std::size_t h = 0; h < closures.size(); ++h)
    if (closures[h] != before[h]) setClosure(static_cast<sim::Hand>(h), closures[h]);
  previous_ = state;

  drive(gamepadCommand(state, options_.scale), dtS);
}

}  // namespace microsim::tracking
