#pragma once
// The same OpenGL context request as the app's main(), for tests that show a viewport.
#include <QSurfaceFormat>

namespace microsim::gui {

inline void requestCoreProfile() {
  QSurfaceFormat format;
  format.setVersion(3, 3);
  format.setProfile(QSurfaceFormat::CoreProfile);
  format.setDepthBufferSize(24);
  QSurfaceFormat::setDefaultFormat(format);
}

}  // namespace microsim::gui
