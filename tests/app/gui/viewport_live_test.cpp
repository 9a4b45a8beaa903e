// The viewport on a running simulation, the way microsim-view-measure drives it: the app's
// surface format (multisampled), a pose submitted to the live runner reaching a presented
// frame, and a frame handler ending the application's event loop.
#include "gui/render/surface_format.h"
#include "gui/simulation_runner.h"
#include "gui/viewport.h"

#include <QApplication>
#include <QImage>
#include <QOpenGLContext>
#include <QSignalSpy>
#include <QTest>
#include <QTimer>

#include "app/gui/core_profile.h"
#include "support/shipped_files.h"

#include <gtest/gtest.h>

#include <memory>
#include <set>

namespace microsim::gui {
namespace {

using microsim::testing::kShippedScene;

// the right forceps' position in the snapshot the viewport last drew
Eigen::Vector3d drawnRightForceps(const Viewport& view) {
  return view.drawnSnapshot()->forceps[1].pose.block<3, 1>(0, 3).cast<double>();
}

// a 320 × 200 viewport on the anastomosis scene, loaded in `mode` with the current default
// surface format, not yet shown
struct SceneView {
  SimulationRunner runner;
  std::unique_ptr<Viewport> view;

  explicit SceneView(sim::StepMode mode) {
    EXPECT_TRUE(runner.load(kShippedScene, mode));
    view = std::make_unique<Viewport>();
    view->resize(320, 200);
    view->setRunner(&runner);
  }
};

TEST(SurfaceFormat, IsTheCoreProfileTheShadersNeed) {
  const QSurfaceFormat format = microscopeSurfaceFormat();
  EXPECT_EQ(format.majorVersion(), 3);
  EXPECT_EQ(format.minorVersion(), 3);
  EXPECT_EQ(format.profile(), QSurfaceFormat::CoreProfile);
  EXPECT_EQ(format.depthBufferSize(), 24);
  EXPECT_EQ(format.samples(), kMicroscopeSamples);
  EXPECT_EQ(microscopeSurfaceFormat(0).samples(), 0);
}

TEST(SurfaceFormat, TheAppsMultisampledFormatDrawsTheScene) {
  useMicroscopeSurfaceFormat();
  SceneView s(sim::StepMode::Deterministic);
  requestCoreProfile();  // the other GUI tests draw without multisampling; this view keeps its format
  QSignalSpy frames(s.view.get(), &Viewport::frameDrawn);
  s.view->show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(s.view.get()));
  ASSERT_TRUE(frames.count() > 0 || frames.wait(10000));
  EXPECT_TRUE(s.view->lastError().isEmpty()) << s.view->lastError().toStdString();
  const QSurfaceFormat actual = s.view->context()->format();
  EXPECT_EQ(actual.profile(), QSurfaceFormat::CoreProfile);
  EXPECT_GE(actual.majorVersion() * 10 + actual.minorVersion(), 33);
  // a shaded scene, not a cleared or failed framebuffer
  const QImage image = s.view->grabFramebuffer();
  std::set<QRgb> colours;
  for (int y = 0; y < image.height(); y += 4)
    for (int x = 0; x < image.width(); x += 4) colours.insert(image.pixel(x, y));
  EXPECT_GT(colours.size(), 30u);
}

TEST(Viewport, PresentsAToolPoseSubmittedToTheLiveRunner) {
  requestCoreProfile();
  SceneView s(sim::StepMode::RealTime);
  Viewport& view = *s.view;
  view.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&view));
  s.runner.start();

  sim::InputFrame frame;
  frame.hand(sim::Hand::Right).tracked = true;
  frame.hand(sim::Hand::Right).position = Eigen::Vector3d(1.2, -0.3, 0.9);
  s.runner.submitFrame(frame);
  // each presented frame is checked; the runner's snapshots alone keep the viewport redrawing
  bool shown = false;
  QObject::connect(&view, &QOpenGLWidget::frameSwapped, &view, [&] {
    if (view.drawnSnapshot() && (drawnRightForceps(view) - frame.hand(sim::Hand::Right).position).norm() < 1e-5)
      shown = true;
  });
  QTRY_VERIFY_WITH_TIMEOUT(shown, 10000);
  s.runner.stop();
  EXPECT_TRUE(view.lastError().isEmpty()) << view.lastError().toStdString();
}

TEST(Viewport, AFrameHandlerCanEndTheApplicationLoop) {
  // QApplication::quit closes every window at once; called straight from a frameDrawn handler
  // (inside paintGL) it destroyed the native window Qt was about to flush that frame to
  // (SIGSEGV in QXcbWindow::needsSync), so microsim-view-measure queues it, as here
  requestCoreProfile();
  SceneView s(sim::StepMode::RealTime);
  Viewport& view = *s.view;
  SimulationRunner& runner = s.runner;
  int drawn = 0;
  QObject::connect(&view, &Viewport::frameDrawn, &view, [&] {
    if (++drawn == 1) runner.start();
    if (drawn == 5) {
      QTimer::singleShot(0, qApp, [&runner] {
        runner.stop();
        QCoreApplication::quit();
      });
      return;
    }
    QTimer::singleShot(0, &view, qOverload<>(&QWidget::update));
  });
  QTimer guard;  // a hang guard only: without frames the loop would never end
  guard.setSingleShot(true);
  QObject::connect(&guard, &QTimer::timeout, qApp, &QCoreApplication::quit);
  guard.start(30000);
  view.show();
  EXPECT_EQ(QApplication::exec(), 0);
  EXPECT_GE(drawn, 5);
  EXPECT_FALSE(runner.isRunning());
}

}  // namespace
}  // namespace microsim::gui
