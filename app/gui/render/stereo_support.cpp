#include "gui/render/stereo_support.h"

#include <QtGlobal>

#if QT_VERSION >= QT_VERSION_CHECK(6, 5, 0)
#include <QOpenGLContext>
#include <QSurfaceFormat>
#endif

namespace microsim::gui {

namespace {

bool probeQuadBufferStereo() {
#if QT_VERSION < QT_VERSION_CHECK(6, 5, 0)
  // QOpenGLWidget renders into a texture without left/right buffers before 6.5
  return false;
#else
  // what the display gives, not what was asked for: a request for stereo is quietly dropped
  // where no stereo visual exists (Xvfb, most desktops)
  QOpenGLContext context;
  context.setFormat(QSurfaceFormat::defaultFormat());
  return context.create() && context.format().stereo();
#endif
}

}  // namespace

bool quadBufferStereoAvailable() {
  static const bool available = probeQuadBufferStereo();
  return available;
}

}  // namespace microsim::gui
