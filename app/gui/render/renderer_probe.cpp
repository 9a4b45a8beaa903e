#include "gui/render/renderer_probe.h"

#include "gui/render/surface_format.h"

#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions>

namespace microsim::gui {

namespace {

QString askOpenGlRendererName() {
  QOffscreenSurface surface;
  surface.create();
  QOpenGLContext context;
  if (!context.create() || !context.makeCurrent(&surface)) return {};
  const auto* name = reinterpret_cast<const char*>(context.functions()->glGetString(GL_RENDERER));
  QString renderer = name ? QString::fromLatin1(name) : QString();
  context.doneCurrent();
  return renderer;
}

}  // namespace

QString openGlRendererName() {
  static const QString name = askOpenGlRendererName();
  return name;
}

bool isSoftwareRenderer(const QString& rendererName) {
  static const char* const kSoftware[] = {"llvmpipe", "softpipe", "swiftshader", "gdi generic",
                                          "software rasterizer", "apple software renderer"};
  const QString name = rendererName.toLower();
  for (const char* s : kSoftware)
    if (name.contains(QLatin1String(s))) return true;
  return false;
}

int microscopeSamplesFor(const QString& rendererName) {
  return isSoftwareRenderer(rendererName) ? 0 : kMicroscopeSamples;
}

bool depthOfFieldByDefault(const QString& rendererName) { return !isSoftwareRenderer(rendererName); }

}  // namespace microsim::gui
