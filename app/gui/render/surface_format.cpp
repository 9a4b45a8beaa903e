#include "gui/render/surface_format.h"

namespace microsim::gui {

QSurfaceFormat microscopeSurfaceFormat(int samples) {
  QSurfaceFormat format;
  format.setVersion(3, 3);
  format.setProfile(QSurfaceFormat::CoreProfile);
  format.setDepthBufferSize(24);
  format.setSamples(samples);
  return format;
}

void useMicroscopeSurfaceFormat(int samples) { QSurfaceFormat::setDefaultFormat(microscopeSurfaceFormat(samples)); }

}  // namespace microsim::gui
