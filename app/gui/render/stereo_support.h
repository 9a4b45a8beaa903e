#pragma once
// Which stereo modes this display can show. Anaglyph and side by side draw into any context;
// quad-buffer stereo needs a context with left and right back buffers and a widget that can
// present them, which QOpenGLWidget does only from Qt 6.5. The settings offer only what works
// here, rather than a mode that would silently fall back to another.

namespace microsim::gui {

/// True when a context made with the default surface format (the one every viewport gets)
/// actually has a stereo format (QSurfaceFormat::stereo() on the created context) and the
/// viewport can present its two buffers. Probed on the first call (needs a QGuiApplication);
/// the display does not change while the app runs.
bool quadBufferStereoAvailable();

}  // namespace microsim::gui
