#pragma once
// The app's OpenGL context request (gui/render/surface_format.h) for tests that show a
// viewport, without multisampling so pixel checks see crisp edges.
#include "gui/render/surface_format.h"

namespace microsim::gui {

inline void requestCoreProfile() { useMicroscopeSurfaceFormat(0); }

}  // namespace microsim::gui
