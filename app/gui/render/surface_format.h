#pragma once
// The OpenGL context every microscope viewport needs, asked for in one place: the app's main(),
// the GUI tests and the viewport measurement all take it from here.
//
// 3.3 core profile (the viewport's shaders are GLSL 3.30 core), a 24-bit depth buffer, and
// `samples`-fold multisampling of the viewport's framebuffer (0: none). The app draws with
// kMicroscopeSamples; tests that compare pixels ask for 0 so edges stay crisp.
//
// Set it before QApplication is constructed: on some platforms (macOS) Qt needs the core
// profile in the default format by then, so that the contexts it creates internally for
// QOpenGLWidget share resources with the viewport's. Later still reaches viewports created
// afterwards, which is what the GUI tests rely on (their QApplication exists first).

#include <QSurfaceFormat>

namespace microsim::gui {

/// The app's multisampling of the viewport (samples per pixel).
inline constexpr int kMicroscopeSamples = 4;

/// The viewport's context request with `samples` samples per pixel (0: no multisampling).
QSurfaceFormat microscopeSurfaceFormat(int samples = kMicroscopeSamples);

/// Makes microscopeSurfaceFormat(samples) the default format of every new context and window.
void useMicroscopeSurfaceFormat(int samples = kMicroscopeSamples);

}  // namespace microsim::gui
