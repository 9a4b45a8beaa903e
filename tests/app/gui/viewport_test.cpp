#include "gui/viewport.h"

#include "app/gui/core_profile.h"
#include "gui/render/side_view.h"
#include "gui/simulation_runner.h"
#include "tracking/manual_source.h"
#include "support/queued_signal_spy.h"
#include "support/shipped_files.h"

#include <QApplication>
#include <QImage>
#include <QLineF>
#include <QSignalSpy>
#include <QTest>
#include <QWheelEvent>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <vector>

namespace microsim::gui {
namespace {

using microsim::testing::kShippedScene;

bool reddish(QRgb c) { return qRed(c) > qGreen(c) + 50 && qRed(c) > 90; }
bool drape(QRgb c) { return qGreen(c) > qRed(c) + 10 && qBlue(c) > qRed(c) + 10; }
bool threadBlue(QRgb c) { return qBlue(c) > qRed(c) + 50 && qBlue(c) > qGreen(c) + 30; }
bool guideGreen(QRgb c) { return qGreen(c) > qRed(c) + 80 && qGreen(c) > qBlue(c) + 50; }
// the instruments' non-glare grey, lighter than the side view's backdrop (about 100)
bool jawMetal(QRgb c) {
  return qRed(c) > 120 && std::abs(qRed(c) - qGreen(c)) < 25 && std::abs(qGreen(c) - qBlue(c)) < 30;
}

// a viewport at 800 × 600 on a loaded (not running) anastomosis scene
struct Fixture {
  SimulationRunner runner;
  std::unique_ptr<Viewport> view;

  Fixture() {
    requestCoreProfile();
    EXPECT_TRUE(runner.load(kShippedScene, sim::StepMode::Deterministic));
    view = std::make_unique<Viewport>();
    view->resize(800, 600);
    view->setRunner(&runner);
  }

  QImage draw() {
    QSignalSpy frames(view.get(), &Viewport::frameDrawn);
    if (!view->isVisible()) {
      view->show();
      EXPECT_TRUE(QTest::qWaitForWindowExposed(view.get()));
    } else {
      view->update();
    }
    EXPECT_TRUE(frames.count() > 0 || frames.wait(10000));
    EXPECT_TRUE(view->lastError().isEmpty()) << view->lastError().toStdString();
    return view->grabFramebuffer();
  }

  // steps the scene once with this frame and waits for its snapshot; the runner signals from
  // its own thread, so the spy takes the call through this thread's event queue
  void replay(const sim::InputFrame& frame) {
    microsim::testing::QueuedSignalSpy done(&runner, &SimulationRunner::replayFinished);
    runner.replay({frame});
    EXPECT_TRUE(done.count() > 0 || done.wait(10000));
  }

  // where a scene point lands in the side view's inset (pixels)
  std::optional<QPoint> projectSide(const Eigen::Vector3d& p) const {
    const MicroscopeCamera side = sideViewCamera(view->camera());
    const QRect area = sideViewArea(view->size());
    const QMatrix4x4 m = side.projection(static_cast<float>(area.width()) / static_cast<float>(area.height())) * side.view();
    const QVector4D clip = m * QVector4D(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z()), 1.0f);
    if (clip.w() <= 0.0f) return std::nullopt;
    const QPoint px(area.x() + qRound((clip.x() / clip.w() + 1.0f) * 0.5f * static_cast<float>(area.width())),
                    area.y() + qRound((1.0f - clip.y() / clip.w()) * 0.5f * static_cast<float>(area.height())));
    if (!area.adjusted(2, 2, -2, -2).contains(px)) return std::nullopt;
    return px;
  }

  // where a scene point lands on the image (pixels), through the centre eye
  std::optional<QPoint> project(const Eigen::Vector3d& p, const QImage& image, Eye eye = Eye::Centre,
                                int x0 = 0, int width = -1) const {
    const int w = width < 0 ? image.width() : width;
    const QMatrix4x4 m = view->camera().projection(static_cast<float>(w) / static_cast<float>(image.height()), eye) *
                         view->camera().view(eye);
    const QVector4D clip = m * QVector4D(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z()), 1.0f);
    if (clip.w() <= 0.0f) return std::nullopt;
    const QPoint px(x0 + qRound((clip.x() / clip.w() + 1.0f) * 0.5f * static_cast<float>(w)),
                    qRound((1.0f - clip.y() / clip.w()) * 0.5f * static_cast<float>(image.height())));
    if (px.x() < 2 || px.y() < 2 || px.x() >= x0 + w - 2 || px.y() >= image.height() - 2) return std::nullopt;
    return px;
  }
};

bool anyNear(const QImage& image, QPoint at, int radius, bool (*test)(QRgb)) {
  for (int dy = -radius; dy <= radius; ++dy)
    for (int dx = -radius; dx <= radius; ++dx) {
      const QPoint p = at + QPoint(dx, dy);
      if (image.valid(p) && test(image.pixel(p))) return true;
    }
  return false;
}

TEST(Viewport, ShowsTheVesselWhereItProjectsAndTheBackgroundElsewhere) {
  Fixture f;
  const QImage image = f.draw();
  ASSERT_FALSE(image.isNull());
  EXPECT_GE(f.view->drawnStep(), 0);
  // the top of each vessel end, seen from the microscope (the ends span |x| in [0.25, 3.25])
  const Eigen::Vector3d toEye = (f.runner.sceneDef()->camera.eye - f.runner.sceneDef()->camera.target).normalized();
  for (double x : {-2.0, -1.0, 1.0, 2.0}) {
    const auto p = f.project(Eigen::Vector3d(x, 0.0, 0.0) + 0.5 * toEye, image);
    ASSERT_TRUE(p) << x;
    EXPECT_TRUE(reddish(image.pixel(*p))) << "x = " << x << ": " << std::hex << image.pixel(*p);
  }
  // beside the vessel and in the gap between its ends: the background plane
  for (const Eigen::Vector3d& q : {Eigen::Vector3d(0.0, 2.5, 0.0), Eigen::Vector3d(-2.0, -2.0, 0.0),
                                   Eigen::Vector3d(0.0, 0.0, 0.0)}) {
    const auto p = f.project(q, image);
    ASSERT_TRUE(p);
    EXPECT_TRUE(drape(image.pixel(*p))) << q.transpose() << ": " << std::hex << image.pixel(*p);
  }
}

// the microscope zoomed out until the whole thread lies inside the circular field of view
void zoomOutToTheWholeThread(Fixture& f) {
  f.view->camera().zoom(-12.0f);
  f.view->cameraChanged();
}

// where every third node of the thread in the runner's latest snapshot lands on the image
std::vector<QPoint> threadNodesOnImage(const Fixture& f, const QImage& image) {
  const auto s = f.runner.latestSnapshot();
  EXPECT_TRUE(s);
  std::vector<QPoint> points;
  if (!s) return points;
  const int nodes = static_cast<int>(s->suturePositions.size() / 3);
  EXPECT_GT(nodes, s->needleNodes + 10);
  for (int i = s->needleNodes + 2; i < nodes; i += 3) {
    const auto k = 3 * static_cast<std::size_t>(i);
    const auto p = f.project(Eigen::Vector3d(s->suturePositions[k], s->suturePositions[k + 1], s->suturePositions[k + 2]), image);
    if (p) points.push_back(*p);
  }
  return points;
}

TEST(Viewport, DrawsTheSutureAsATubeWhereTheSnapshotHasIt) {
  Fixture f;
  zoomOutToTheWholeThread(f);
  const QImage image = f.draw();
  const std::vector<QPoint> nodes = threadNodesOnImage(f, image);
  const auto visible = static_cast<int>(nodes.size());
  int found = 0;
  for (const QPoint& p : nodes) found += anyNear(image, p, 2, threadBlue) ? 1 : 0;
  ASSERT_GE(visible, 3);
  EXPECT_GE(found, visible * 8 / 10) << found << " of " << visible;
  // and nowhere far from it: the image's blue pixels are few
  int blue = 0;
  for (int y = 0; y < image.height(); y += 2)
    for (int x = 0; x < image.width(); x += 2) blue += threadBlue(image.pixel(x, y)) ? 1 : 0;
  EXPECT_LT(blue, image.width() * image.height() / 4 / 20);
}

TEST(Viewport, AnaglyphPutsTheLeftEyeInRedAndTheRightEyeInCyan) {
  Fixture f;
  // a near focal plane: the vessel lies far behind it, so the two eyes see it well apart
  f.view->camera().setFocusDistance(f.view->camera().distance() * 0.5f);
  f.view->cameraChanged();
  const QImage mono = f.draw();
  f.view->setStereoMode(StereoMode::Anaglyph);
  EXPECT_EQ(f.view->effectiveStereoMode(), StereoMode::Anaglyph);
  const QImage ana = f.draw();
  // the red channel is the left eye's: it sees the pale vessel where the centre eye sees the
  // dark drape (red up, green as before), and the drape where the centre eye sees the vessel
  // (red down, while the right eye's green holds)
  int redOnly = 0;
  int cyanOnly = 0;
  for (int y = 0; y < ana.height(); y += 2) {
    for (int x = 0; x < ana.width(); x += 2) {
      const QRgb m = mono.pixel(x, y);
      const QRgb a = ana.pixel(x, y);
      if (qRed(a) > qRed(m) + 60 && qGreen(a) < qGreen(m) + 10) ++redOnly;
      if (qRed(a) + 60 < qRed(m) && qGreen(a) + 10 > qGreen(m)) ++cyanOnly;
    }
  }
  EXPECT_GT(redOnly, 50) << redOnly;
  EXPECT_GT(cyanOnly, 50) << cyanOnly;
  // the right eye alone is in green and blue: they do not equal the mono image's everywhere
  int greenDiffers = 0;
  for (int y = 0; y < ana.height(); y += 2)
    for (int x = 0; x < ana.width(); x += 2) greenDiffers += std::abs(qGreen(ana.pixel(x, y)) - qGreen(mono.pixel(x, y))) > 30;
  EXPECT_GT(greenDiffers, 100);

  // no stereo buffers here: quad-buffer falls back to anaglyph
  f.view->setStereoMode(StereoMode::QuadBuffer);
  if (!f.view->quadBufferAvailable()) {
    EXPECT_EQ(f.view->effectiveStereoMode(), StereoMode::Anaglyph);
  }
}

TEST(Viewport, SideBySideDrawsOneEyeInEachHalf) {
  Fixture f;
  f.view->setStereoMode(StereoMode::SideBySide);
  const QImage image = f.draw();
  const int half = image.width() / 2;
  const Eigen::Vector3d toEye = (f.runner.sceneDef()->camera.eye - f.runner.sceneDef()->camera.target).normalized();
  for (double x : {-2.0, 2.0}) {
    const Eigen::Vector3d top = Eigen::Vector3d(x, 0.0, 0.0) + 0.5 * toEye;
    const auto left = f.project(top, image, Eye::Left, 0, half);
    const auto right = f.project(top, image, Eye::Right, half, image.width() - half);
    ASSERT_TRUE(left && right);
    EXPECT_TRUE(reddish(image.pixel(*left))) << std::hex << image.pixel(*left);
    EXPECT_TRUE(reddish(image.pixel(*right))) << std::hex << image.pixel(*right);
    EXPECT_NEAR(left->x() + half, right->x(), 0.05 * half);
  }
  // the centre column of each half crosses the vessel's gap, the seam between them does not
  // show the vessel's middle: each half is its own picture
  EXPECT_TRUE(drape(image.pixel(half / 2, image.height() / 2)) || !reddish(image.pixel(half / 2, image.height() / 2)));
}

TEST(Viewport, DrawsGuidesAsRingsAndArrows) {
  Fixture f;
  Guide ring;
  ring.kind = Guide::Kind::Target;
  ring.point = Eigen::Vector3d(0.0, 2.0, 0.5);
  ring.direction = Eigen::Vector3d::UnitZ();
  ring.size = 0.3;
  Guide arrow;
  arrow.kind = Guide::Kind::NeedleDirection;
  arrow.point = Eigen::Vector3d(-2.0, -2.0, 0.5);
  arrow.direction = Eigen::Vector3d::UnitX();
  arrow.size = 1.0;
  f.view->setGuides({ring, arrow});
  const QImage image = f.draw();
  const auto onRing = f.project(ring.point + Eigen::Vector3d(0.3, 0.0, 0.0), image);
  const auto centre = f.project(ring.point, image);
  const auto shaft = f.project(arrow.point + Eigen::Vector3d(0.4, 0.0, 0.0), image);
  ASSERT_TRUE(onRing && centre && shaft);
  EXPECT_TRUE(anyNear(image, *onRing, 2, guideGreen));
  EXPECT_FALSE(guideGreen(image.pixel(*centre)));  // a ring, not a disc
  EXPECT_TRUE(anyNear(image, *shaft, 2, guideGreen));
  f.view->setGuides({});
  const QImage cleared = f.draw();
  EXPECT_FALSE(anyNear(cleared, *onRing, 2, guideGreen));
}

TEST(Viewport, TheSideViewShowsAToolAboveTheTissue) {
  Fixture f;
  // the right forceps upright, its open jaws' tip 1.5 mm above the top of the left vessel end
  sim::InputFrame frame;
  frame.time = 0.01;
  sim::HandInput& hand = frame.hand(sim::Hand::Right);
  hand.tracked = true;
  hand.position = Eigen::Vector3d(-1.5, 0.0, 2.0);
  Eigen::Matrix3d upright;
  upright << 0, 0, -1,  //
      0, 1, 0,          //
      1, 0, 0;
  hand.orientation = Eigen::Quaterniond(upright);
  f.replay(frame);
  const QImage image = f.draw();

  // in the inset: the jaws above the tip, the vessel's wall below it, the inset's own
  // background between them
  const auto jaw = f.projectSide(Eigen::Vector3d(-1.5, 0.0, 3.2));
  const auto wall = f.projectSide(Eigen::Vector3d(-1.5, 0.0, 0.2));
  const auto gap = f.projectSide(Eigen::Vector3d(-1.5, 0.0, 1.2));
  ASSERT_TRUE(jaw && wall && gap);
  EXPECT_TRUE(anyNear(image, *jaw, 2, jawMetal)) << std::hex << image.pixel(*jaw);
  EXPECT_TRUE(reddish(image.pixel(*wall))) << std::hex << image.pixel(*wall);
  EXPECT_FALSE(anyNear(image, *gap, 2, jawMetal)) << std::hex << image.pixel(*gap);
  EXPECT_FALSE(anyNear(image, *gap, 2, reddish)) << std::hex << image.pixel(*gap);
  EXPECT_LT(jaw->y(), gap->y());
  EXPECT_LT(gap->y(), wall->y());

  // without the inset the corner shows the microscope's view: no tool there
  f.view->setSideViewVisible(false);
  const QImage plain = f.draw();
  EXPECT_FALSE(anyNear(plain, *jaw, 2, jawMetal));
}

// ---- the microscope's look (issue #20, item 7) -----------------------------------------------

int luminance(QRgb c) { return (299 * qRed(c) + 587 * qGreen(c) + 114 * qBlue(c)) / 1000; }

TEST(Viewport, TheFieldOfViewIsACircleBlackOutsideAndTheSideViewIsNotMasked) {
  Fixture f;
  const QImage image = f.draw();
  ASSERT_EQ(image.height(), 600);
  // three corners black (the fourth holds the side view); the middle of the field bright
  for (const QPoint corner : {QPoint(3, 3), QPoint(3, image.height() - 4), QPoint(image.width() - 4, image.height() - 4)})
    EXPECT_LT(luminance(image.pixel(corner)), 8) << corner.x() << ", " << corner.y() << ": " << std::hex << image.pixel(corner);
  const QPoint middle(image.width() / 2, image.height() / 2);
  EXPECT_GT(luminance(image.pixel(middle)), 40) << std::hex << image.pixel(middle);
  // the field is as wide as the smaller side: bright at 80 % of its radius along the long
  // side, black just beyond it
  const int radius = image.height() / 2;
  EXPECT_GT(luminance(image.pixel(middle + QPoint(-8 * radius / 10, 0))), 25);
  EXPECT_LT(luminance(image.pixel(middle + QPoint(-radius - 4, 0))), 8);
  // the side view in the top-right corner keeps its own background, unmasked
  const QRect inset = sideViewArea(f.view->size());
  EXPECT_GT(luminance(image.pixel(inset.topRight() + QPoint(-6, 6))), 40);
}

TEST(Viewport, TheWallIsTexturedNotOneFlatColourAlongTheVessel) {
  Fixture f;
  f.view->setDepthOfField(false);
  const QImage image = f.draw();
  // along the top of the left vessel end the cylinder's lighting is the same at every x: what
  // varies there is the wall's texture
  const Eigen::Vector3d toEye = (f.runner.sceneDef()->camera.eye - f.runner.sceneDef()->camera.target).normalized();
  std::vector<int> greens;
  for (int k = 0; k <= 120; ++k) {
    const double x = -3.0 + 0.02 * k;  // -3.0 … -0.6 mm
    const auto p = f.project(Eigen::Vector3d(x, 0.0, 0.0) + 0.5 * toEye, image);
    ASSERT_TRUE(p);
    const QRgb c = image.pixel(*p);
    ASSERT_TRUE(reddish(c)) << x << ": " << std::hex << c;
    greens.push_back(qGreen(c));
  }
  double mean = 0.0;
  for (int g : greens) mean += g;
  mean /= static_cast<double>(greens.size());
  double variance = 0.0;
  for (int g : greens) variance += (g - mean) * (g - mean);
  variance /= static_cast<double>(greens.size());
  EXPECT_GT(std::sqrt(variance), 4.0) << "a flat-coloured cylinder varies by about 0 here";
}

TEST(Viewport, TheThreadContrastsWithWhatIsAroundIt) {
  Fixture f;
  // far out: the thread is as thin as the viewport ever draws it (about a pixel's radius)
  zoomOutToTheWholeThread(f);
  const QImage image = f.draw();
  int visible = 0;
  int contrasting = 0;
  for (const QPoint& node : threadNodesOnImage(f, image)) {
    if (QLineF(node, QPointF(400, 300)).length() > 270.0) continue;  // within the field
    ++visible;
    // the thread pixel near the node against the brightest pixel a few pixels around it
    int thread = 255;
    int around = 0;
    for (int dy = -5; dy <= 5; ++dy)
      for (int dx = -5; dx <= 5; ++dx) {
        const QPoint q = node + QPoint(dx, dy);
        if (!image.valid(q)) continue;
        const int l = luminance(image.pixel(q));
        if (std::abs(dx) <= 2 && std::abs(dy) <= 2 && threadBlue(image.pixel(q))) thread = std::min(thread, l);
        around = std::max(around, l);
      }
    if (thread < 255 && around - thread >= 50) ++contrasting;
  }
  ASSERT_GE(visible, 3);
  EXPECT_GE(contrasting, visible * 8 / 10) << contrasting << " of " << visible;
}

// summed |difference| of horizontally adjacent pixels over `area`: the picture's sharpness
long gradientEnergy(const QImage& image, const QRect& area) {
  long sum = 0;
  for (int y = area.top(); y <= area.bottom(); ++y)
    for (int x = area.left(); x < area.right(); ++x) sum += std::abs(luminance(image.pixel(x + 1, y)) - luminance(image.pixel(x, y)));
  return sum;
}

TEST(Viewport, DepthOfFieldBlursWhatLiesOffTheFocalPlaneAndCanBeTurnedOff) {
  Fixture f;
  EXPECT_TRUE(f.view->depthOfField());
  const QImage focused = f.draw();
  // the focal plane well above the vessel: the vessel is out of focus
  f.view->camera().setFocusDistance(f.view->camera().distance() * 0.8f);
  f.view->cameraChanged();
  const QImage blurred = f.draw();
  f.view->setDepthOfField(false);
  const QImage sharp = f.draw();
  // around the gap between the vessel's ends: its edges and the wall's texture
  const auto a = f.project(Eigen::Vector3d(-1.5, -0.6, 0.0), sharp);
  const auto b = f.project(Eigen::Vector3d(1.5, 0.6, 0.0), sharp);
  ASSERT_TRUE(a && b);
  const QRect area = QRect(*a, *b).normalized();
  ASSERT_GT(area.width(), 50);
  const long onBlurred = gradientEnergy(blurred, area);
  const long offSharp = gradientEnergy(sharp, area);
  const long onFocused = gradientEnergy(focused, area);
  EXPECT_GT(offSharp, onBlurred * 13 / 10) << offSharp << " against " << onBlurred;
  // in focus the vessel is as sharp with depth of field as without it
  EXPECT_GT(onFocused, onBlurred * 13 / 10) << onFocused << " against " << onBlurred;
}

TEST(Viewport, KeysDriveTheManualSourceAndF1ShowsTheHelp) {
  Fixture f;
  tracking::ManualSource source;
  f.view->setManualSource(&source);
  QSignalSpy frames(&source, &tracking::TrackerSource::frameReady);
  QObject::connect(&source, &tracking::TrackerSource::frameReady, &f.runner, &SimulationRunner::submitFrame);
  source.start();
  f.draw();
  f.view->setFocus();
  const Eigen::Vector3d p0 = source.current().hand(sim::Hand::Right).position;
  const Eigen::Vector3d right(f.view->camera().right().x(), f.view->camera().right().y(), f.view->camera().right().z());
  QTest::keyClick(f.view.get(), Qt::Key_D);
  QTest::keyClick(f.view.get(), Qt::Key_D);
  QTest::keyClick(f.view.get(), Qt::Key_A, Qt::ShiftModifier);
  const Eigen::Vector3d moved = source.current().hand(sim::Hand::Right).position;
  EXPECT_LT((moved - p0 - (2 * tracking::ManualSource::kStepMm - tracking::ManualSource::kFineStepMm) * right).norm(), 1e-6);
  EXPECT_EQ(frames.last().at(0).value<sim::InputFrame>().hand(sim::Hand::Right).position, moved);
  QTest::keyClick(f.view.get(), Qt::Key_Tab);
  EXPECT_EQ(source.activeHand(), sim::Hand::Left);

  EXPECT_FALSE(f.view->helpVisible());
  const QImage before = f.draw();
  QTest::keyClick(f.view.get(), Qt::Key_F1);
  EXPECT_TRUE(f.view->helpVisible());
  const QImage help = f.draw();
  EXPECT_NE(before, help);
}

Eigen::Vector3d viewportTestAxis(const QVector3D& v) { return {v.x(), v.y(), v.z()}; }

// the tools placed on the fixture's scene and driven by `source`, through the drawn viewport
void viewportTestDriveBy(Fixture& f, tracking::ManualSource& source) {
  source.placeTools(*f.runner.sceneDef());
  f.view->setManualSource(&source);
  source.start();
  f.draw();
}

// one wheel notch (positive: turned away from the user) with `modifiers`, at the centre
void viewportTestWheel(QWidget* widget, int notches, Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
  const QPointF at(widget->width() / 2.0, widget->height() / 2.0);
  QWheelEvent wheel(at, widget->mapToGlobal(at), QPoint(), QPoint(0, 120 * notches), Qt::NoButton, modifiers,
                    Qt::NoScrollPhase, false);
  QApplication::sendEvent(widget, &wheel);
}

// The mouse is the hand first: a left drag carries the active tip with the cursor, the wheel
// moves it in depth, a right click closes or opens its jaws and a right drag closes them by
// degrees; the camera takes Shift: Shift + left drag orbits and leaves the tool where it is.
TEST(Viewport, TheMouseMovesTheToolInTheViewAndInDepthAndWorksItsJaws) {
  Fixture f;
  tracking::ManualSource source;
  viewportTestDriveBy(f, source);
  MicroscopeCamera& camera = f.view->camera();
  const Eigen::Vector3d right = viewportTestAxis(camera.right());
  const Eigen::Vector3d up = viewportTestAxis(camera.up());
  const Eigen::Vector3d toward = -viewportTestAxis(camera.forward());
  const double pixel = camera.mmPerPixel(f.view->height());
  const auto tip = [&] { return source.current().hand(sim::Hand::Right).position; };
  const auto closure = [&] { return source.current().hand(sim::Hand::Right).closure; };
  const Eigen::Vector3d p0 = tip();

  QTest::mousePress(f.view.get(), Qt::LeftButton, {}, QPoint(400, 300));
  QTest::mouseMove(f.view.get(), QPoint(420, 295));
  QTest::mouseMove(f.view.get(), QPoint(440, 280));
  QTest::mouseRelease(f.view.get(), Qt::LeftButton, {}, QPoint(440, 280));
  EXPECT_LT((tip() - (p0 + pixel * (40.0 * right + 20.0 * up))).norm(), 1e-6);

  const Eigen::Vector3d p1 = tip();
  viewportTestWheel(f.view.get(), 1);
  EXPECT_LT((tip() - (p1 - 0.1 * toward)).norm(), 1e-6) << "turned away: deeper";
  viewportTestWheel(f.view.get(), -3);
  EXPECT_LT((tip() - (p1 + 0.2 * toward)).norm(), 1e-6);

  EXPECT_EQ(closure(), 0.0);
  QTest::mouseClick(f.view.get(), Qt::RightButton, {}, QPoint(300, 300));
  EXPECT_EQ(closure(), 1.0);
  QTest::mouseClick(f.view.get(), Qt::RightButton, {}, QPoint(300, 300));
  EXPECT_EQ(closure(), 0.0);
  QTest::mousePress(f.view.get(), Qt::RightButton, {}, QPoint(300, 200));
  QTest::mouseMove(f.view.get(), QPoint(300, 230));
  QTest::mouseMove(f.view.get(), QPoint(300, 275));
  QTest::mouseRelease(f.view.get(), Qt::RightButton, {}, QPoint(300, 275));
  EXPECT_NEAR(closure(), 0.5, 1e-9) << "75 of the 150 pixels that close them";

  const Eigen::Vector3d p2 = tip();
  const QVector3D across = camera.right();
  QTest::mousePress(f.view.get(), Qt::LeftButton, Qt::ShiftModifier, QPoint(400, 300));
  QTest::mouseEvent(QTest::MouseMove, f.view.get(), Qt::NoButton, Qt::ShiftModifier, QPoint(460, 300));
  QTest::mouseRelease(f.view.get(), Qt::LeftButton, Qt::ShiftModifier, QPoint(460, 300));
  EXPECT_EQ(tip(), p2);
  EXPECT_NEAR(std::acos(std::clamp(QVector3D::dotProduct(across, camera.right()), -1.0f, 1.0f)) * 180.0 / 3.14159265358979,
              9.0, 0.01) << "60 pixels at 0.15°/px, about the table's normal";
  EXPECT_LT(std::abs(QVector3D::dotProduct(camera.right(), camera.tableNormal())), 1e-5f);
}

// Home and 1 / 2 / 3 show the named views whatever the camera did; the view basis the keys
// move the tool in follows.
TEST(Viewport, HomeAndTheNumberKeysShowTheNamedViews) {
  Fixture f;
  tracking::ManualSource source;
  viewportTestDriveBy(f, source);
  f.view->setFocus();
  MicroscopeCamera& camera = f.view->camera();
  const QVector3D home = camera.eye();
  QTest::keyClick(f.view.get(), Qt::Key_1);
  EXPECT_LT((camera.forward() + camera.tableNormal()).length(), 1e-5f);
  QTest::keyClick(f.view.get(), Qt::Key_3);
  EXPECT_LT(std::abs(QVector3D::dotProduct(camera.forward(), camera.tableNormal())), 1e-5f);
  // in the side view W lifts the tool off the table
  const double height = source.current().hand(sim::Hand::Right).position.z();
  QTest::keyClick(f.view.get(), Qt::Key_W);
  EXPECT_NEAR(source.current().hand(sim::Hand::Right).position.z() - height, tracking::ManualSource::kStepMm, 1e-6);
  QTest::keyClick(f.view.get(), Qt::Key_2);
  EXPECT_NEAR(QVector3D::dotProduct(camera.forward(), camera.tableNormal()), -std::sqrt(0.5f), 1e-5f);
  camera.orbit(20.0f, 5.0f);
  QTest::keyClick(f.view.get(), Qt::Key_Home);
  EXPECT_LT((camera.eye() - home).length(), 1e-4f);
  const QImage microscope = f.draw();
  QTest::keyClick(f.view.get(), Qt::Key_3);
  EXPECT_NE(f.draw(), microscope);
}

}  // namespace
}  // namespace microsim::gui
