#pragma once
// A game controller as a tracker source, through SDL2's game-controller API (Debian:
// libsdl2-dev; SDL maps most pads onto its standard layout). Sticks and D-pad move and turn the
// active tool at a rate, the triggers close the jaws (or the scissors) gradually, the
// shoulders choose the hand, Y swaps the active hand's forceps for the scissors
// (gamepad_mapping.h); frames are in the scene frame (rate_tool_source.h).
//
// start() opens the first game controller SDL finds. Without one it emits linkDown with
// status().lastError saying so and produces nothing; when the controller is unplugged the
// hands are marked untracked (the tools stay) and linkDown follows. The controller is read
// every pollIntervalMs on the owner's thread; with pollIntervalMs = 0 nothing polls it and the
// caller calls advance() (tests step it that way, with a chosen dt).
//
// SDL is started with only its game-controller part (no video, no window) and without its
// signal handlers, so it neither needs a display nor takes Ctrl+C from the app.

#include "tracking/gamepad_mapping.h"
#include "tracking/rate_tool_source.h"

#include <QElapsedTimer>
#include <QString>
#include <QTimer>

#include <memory>

namespace microsim::tracking {

struct GamepadSourceOptions {
  int pollIntervalMs = 10;  ///< ms between readings (100 Hz, the scene's rate); 0: advance() by hand
  GamepadScale scale;
};

class GamepadSource : public RateToolSource {
  Q_OBJECT

 public:
  explicit GamepadSource(GamepadSourceOptions options = {}, QObject* parent = nullptr);
  ~GamepadSource() override;

  void start() override;
  void stop() override;

  /// Reads the controller and moves the tools as for `dtS` seconds at its deflection.
  void advance(double dtS);
  /// The open controller's name as SDL reports it; empty when none is open.
  QString deviceName() const { return name_; }

 private:
  void poll();
  void closeController();

  GamepadSourceOptions options_;
  struct OpenController;  ///< the SDL handle (SDL's headers stay in the .cpp)
  std::unique_ptr<OpenController> controller_;
  QString name_;
  GamepadState previous_;
  QTimer timer_;
  QElapsedTimer sincePoll_;
};

}  // namespace microsim::tracking
