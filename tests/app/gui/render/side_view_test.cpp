// The depth inset's camera and place: at right angles to the microscope, the microscope's
// direction up on screen, the same target and field; in the top-right corner.
#include "gui/render/side_view.h"

#include <gtest/gtest.h>

namespace microsim::gui {
namespace {

TEST(SideView, LooksAtTheTargetAtRightAnglesToTheMicroscope) {
  MicroscopeCamera microscope;
  sim::CameraDef def;
  def.eye = sim::Vec3(0.0, -8.0, 40.0);
  def.target = sim::Vec3(1.0, 0.5, 0.0);
  microscope.reset(def);
  microscope.orbit(25.0f, 10.0f);
  const MicroscopeCamera side = sideViewCamera(microscope);
  EXPECT_NEAR(QVector3D::dotProduct(side.forward(), microscope.forward()), 0.0f, 1e-5f);
  EXPECT_NEAR((side.up() + microscope.forward()).length(), 0.0f, 1e-5f);
  EXPECT_NEAR((side.target() - microscope.target()).length(), 0.0f, 1e-5f);
  EXPECT_NEAR(side.distance(), microscope.distance(), 1e-4f);
  EXPECT_FLOAT_EQ(side.fovDeg(), microscope.fovDeg());
  // a point nearer the microscope is higher in the inset
  const QVector3D raised = microscope.target() - 1.0f * microscope.forward();
  const QVector4D low = side.projection(4.0f / 3.0f) * side.view() * QVector4D(microscope.target(), 1.0f);
  const QVector4D high = side.projection(4.0f / 3.0f) * side.view() * QVector4D(raised, 1.0f);
  EXPECT_GT(high.y() / high.w(), low.y() / low.w() + 0.1f);
}

TEST(SideView, SitsInTheTopRightCorner) {
  const QRect area = sideViewArea(QSize(800, 600));
  EXPECT_EQ(area, QRect(590, 10, 200, 150));
  // never smaller than 96 px wide
  EXPECT_EQ(sideViewArea(QSize(320, 200)).width(), 96);
}

}  // namespace
}  // namespace microsim::gui
