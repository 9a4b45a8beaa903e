#include "gui/render/camera.h"

#include <gtest/gtest.h>

#include <cmath>

namespace microsim::gui {
namespace {

// the shipped scenes' microscope: 40 mm above the table, tilted 11° toward the trainee
sim::CameraDef shippedMicroscope() {
  sim::CameraDef def;
  def.eye = sim::Vec3(0.0, -8.0, 40.0);
  def.target = sim::Vec3(0.0, 0.0, 0.0);
  def.up = sim::Vec3(0.0, 1.0, 0.0);
  def.fovDeg = 12.0;
  return def;
}

float cameraTestGap(const QVector3D& a, const QVector3D& b) { return (a - b).length(); }

TEST(MicroscopeCamera, NamedViewsLookFromAboveFromTheTrainees45DegreesAndFromTheSide) {
  MicroscopeCamera camera;
  camera.reset(shippedMicroscope());
  const float distance = camera.distance();
  EXPECT_LT(cameraTestGap(camera.tableNormal(), QVector3D(0, 0, 1)), 1e-6f);

  camera.showView(NamedView::Top);
  EXPECT_LT(cameraTestGap(camera.forward(), QVector3D(0, 0, -1)), 1e-6f);
  EXPECT_LT(cameraTestGap(camera.up(), QVector3D(0, 1, 0)), 1e-6f);
  EXPECT_NEAR(camera.distance(), distance, 1e-4f);

  camera.showView(NamedView::Oblique);
  const float half = std::sqrt(0.5f);
  EXPECT_LT(cameraTestGap(camera.forward(), QVector3D(0, half, -half)), 1e-6f);
  EXPECT_LT(cameraTestGap(camera.right(), QVector3D(1, 0, 0)), 1e-6f);

  // from the trainee's side: height above the table is up on the screen, the vessel's axis
  // (scene x) runs across it
  camera.showView(NamedView::Side);
  EXPECT_LT(cameraTestGap(camera.forward(), QVector3D(0, 1, 0)), 1e-6f);
  EXPECT_LT(cameraTestGap(camera.up(), QVector3D(0, 0, 1)), 1e-6f);
  EXPECT_LT(cameraTestGap(camera.right(), QVector3D(1, 0, 0)), 1e-6f);
  EXPECT_LT(cameraTestGap(camera.target(), QVector3D(0, 0, 0)), 1e-6f);

  // the microscope view is the scene's, however the camera was moved and zoomed
  camera.orbit(30.0f, 10.0f);
  camera.pan(40.0f, 12.0f, 600);
  camera.zoom(3.0f);
  camera.showView(NamedView::Microscope);
  MicroscopeCamera fresh;
  fresh.reset(shippedMicroscope());
  EXPECT_LT(cameraTestGap(camera.eye(), fresh.eye()), 1e-4f);
  EXPECT_LT(cameraTestGap(camera.up(), fresh.up()), 1e-6f);
  EXPECT_EQ(camera.focusDistance(), fresh.focusDistance());
}

// Orbiting turns about the table's normal and stops at straight down and at the table's level.
TEST(MicroscopeCamera, OrbitTurnsAboutTheTableAndStopsAtTheTopAndAtTheTable) {
  MicroscopeCamera camera;
  camera.reset(shippedMicroscope());
  const float heightBefore = QVector3D::dotProduct(camera.eye(), camera.tableNormal());
  camera.orbit(90.0f, 0.0f);
  EXPECT_NEAR(QVector3D::dotProduct(camera.eye(), camera.tableNormal()), heightBefore, 1e-3f);

  camera.showView(NamedView::Top);
  const QVector3D top = camera.forward();
  camera.orbit(0.0f, 5.0f);  // past straight down: refused
  EXPECT_LT(cameraTestGap(camera.forward(), top), 1e-6f);
  camera.orbit(0.0f, -5.0f);
  EXPECT_GT(QVector3D::dotProduct(camera.up(), camera.tableNormal()), 0.05f);

  camera.showView(NamedView::Side);
  const QVector3D side = camera.forward();
  camera.orbit(0.0f, -5.0f);  // below the table: refused
  EXPECT_LT(cameraTestGap(camera.forward(), side), 1e-6f);
}

}  // namespace
}  // namespace microsim::gui
