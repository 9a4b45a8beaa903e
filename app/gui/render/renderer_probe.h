#pragma once
// Which OpenGL renderer this machine gives the app, asked once at start, so that a software
// rasteriser gets settings that keep the microscope interactive.
//
// On Mesa's llvmpipe (no GPU; the CI machines and many virtual desktops) 4× multisampling
// alone costs 2.4× in frame rate, and the move → frame latency at 1280×800 goes from about
// 60 ms to about 160 ms (README, Viewport speed): there the viewport draws without it. A GPU
// keeps the app's kMicroscopeSamples.

#include <QString>

namespace microsim::gui {

/// The GL_RENDERER string of a context made with the default format on an offscreen surface
/// (needs a QGuiApplication; asked once, then remembered); empty when no context can be made.
QString openGlRendererName();

/// True for renderers that rasterise on the CPU: llvmpipe, softpipe, SwiftShader, Microsoft's
/// GDI generic renderer, Apple's software renderer.
bool isSoftwareRenderer(const QString& rendererName);

/// The multisampling the viewport should ask for on this renderer: none on a software one,
/// else kMicroscopeSamples.
int microscopeSamplesFor(const QString& rendererName);

/// Whether the viewport blurs what lies off the focal plane unless the user said otherwise:
/// on a GPU; not on a software one, where the blur pass costs about a quarter of the frame rate
/// at 1280×800 (README, Viewport speed; the View menu still turns it on).
bool depthOfFieldByDefault(const QString& rendererName);

}  // namespace microsim::gui
