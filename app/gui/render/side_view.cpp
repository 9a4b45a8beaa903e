#include "gui/render/side_view.h"

#include "microsim/sim/scene/scene_def.h"

#include <algorithm>

namespace microsim::gui {

namespace {

sim::Vec3 sideVector(const QVector3D& v) { return {v.x(), v.y(), v.z()}; }

}  // namespace

MicroscopeCamera sideViewCamera(const MicroscopeCamera& microscope) {
  sim::CameraDef def;
  def.target = sideVector(microscope.target());
  def.eye = sideVector(microscope.target() - microscope.distance() * microscope.up());
  def.up = sideVector(-microscope.forward());
  def.fovDeg = microscope.fovDeg();
  MicroscopeCamera side;
  side.reset(def);
  return side;
}

QRect sideViewArea(const QSize& widget) {
  constexpr int kMargin = 10;
  const int width = std::max(96, widget.width() / 4);
  const int height = width * 3 / 4;
  return {widget.width() - kMargin - width, kMargin, width, height};
}

}  // namespace microsim::gui
