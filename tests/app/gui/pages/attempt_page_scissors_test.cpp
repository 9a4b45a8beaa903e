// The microscissors at the real window, as a person uses them: lesson 2 open in Learn mode,
// T takes up the scissors in the right hand, the keys point them down, a left drag brings
// their tip under the thread where the picture shows it (top view: 1.5 mm along the drawn
// thread from its end at the needle; side view: 0.3 mm under its drawn height), a right click
// closes them. The page says the thread was cut and warns that the needle keeps too little
// to tie; the attempt's stored recording replays to the same cut.
#include "gui/number_format.h"
#include "gui/render/side_view.h"

#include "microsim/assessment/storage/attempt_detail.h"
#include "microsim/assessment/storage/people_store.h"
#include "microsim/sim/scene/recording.h"
#include "microsim/sim/scene/scene.h"

#include <QLabel>

#include "app/gui/lesson_at_window.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

namespace microsim::gui {
namespace {

// where the right hand's scissors' tip is drawn
QPoint scissorsTipDrawn(const testing::LessonAtWindow& app) {
  return app.drawnAt(app.drawn().scissors[1].pose.block<3, 1>(0, 3).cast<double>());
}

// the thread's pixels in the picture: its blue, far from the vessel's red and the drape's
// teal; not those of the side view's inset
std::vector<QPoint> threadPixelsDrawn(Viewport& view) {
  const QImage image = view.grabFramebuffer();
  const QRect inset = sideViewArea(view.size());
  std::vector<QPoint> blue;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      if (inset.contains(x, y)) continue;
      const QRgb c = image.pixel(x, y);
      if (qBlue(c) > qRed(c) + 35 && qBlue(c) > qGreen(c) + 35) blue.emplace_back(x, y);
    }
  return blue;
}

// the point `pixels` along the drawn thread from its end nearest `needleSide`
QPoint alongDrawnThread(const std::vector<QPoint>& thread, const QPoint& needleSide, double pixels) {
  // the thread is drawn straight: its direction is the principal axis of its pixels
  double mx = 0.0, my = 0.0;
  for (const QPoint& p : thread) {
    mx += p.x();
    my += p.y();
  }
  mx /= static_cast<double>(thread.size());
  my /= static_cast<double>(thread.size());
  double sxx = 0.0, sxy = 0.0, syy = 0.0;
  for (const QPoint& p : thread) {
    sxx += (p.x() - mx) * (p.x() - mx);
    sxy += (p.x() - mx) * (p.y() - my);
    syy += (p.y() - my) * (p.y() - my);
  }
  const double angle = 0.5 * std::atan2(2.0 * sxy, sxx - syy);
  double dx = std::cos(angle), dy = std::sin(angle);
  // from the end at the needle, outward
  const auto along = [&](const QPoint& p) { return (p.x() - mx) * dx + (p.y() - my) * dy; };
  const auto [lo, hi] = std::minmax_element(thread.begin(), thread.end(),
                                            [&](const QPoint& a, const QPoint& b) { return along(a) < along(b); });
  const QPoint end = (*lo - needleSide).manhattanLength() < (*hi - needleSide).manhattanLength() ? *lo : *hi;
  if (end == *hi) {
    dx = -dx;
    dy = -dy;
  }
  return {qRound(end.x() + pixels * dx), qRound(end.y() + pixels * dy)};
}

TEST(AttemptPageScissors, ScissorsClosedOnTheDrawnThreadCutItAndThePageSaysSo) {
  testing::LessonAtWindow app(1, QStringLiteral("Sam Scissors"));

  // T: the right hand puts its forceps down and takes up the scissors
  app.press(Qt::Key_T);
  ASSERT_TRUE(app.drawn().scissors[1].present);
  EXPECT_EQ(app.drawn().instruments[1], sim::Instrument::Scissors);
  EXPECT_EQ(app.drawn().instruments[0], sim::Instrument::Forceps);

  // top view: the blades turned to point straight down (→ nine times)
  app.press(Qt::Key_1);
  app.press(Qt::Key_Right, 9);
  const double pixelsPerMm = 1.0 / app.view->camera().mmPerPixel(app.view->height());

  // the place to cut: 1.5 mm along the thread as drawn, from its end at the needle
  const std::vector<QPoint> thread = threadPixelsDrawn(*app.view);
  ASSERT_GT(thread.size(), 50u) << "the thread is drawn in the top view";
  const sim::RenderSnapshot& start = app.drawn();
  const std::size_t swage = 3 * static_cast<std::size_t>(start.needleNodes - 1);
  const QPoint needle = app.drawnAt(Eigen::Vector3d(start.suturePositions[swage], start.suturePositions[swage + 1],
                                                    start.suturePositions[swage + 2]));
  const QPoint cutAt = alongDrawnThread(thread, needle, 1.5 * pixelsPerMm);

  // side view: the thread's drawn height, a line through its pixels (it recedes, so it slopes)
  app.press(Qt::Key_3);
  const std::vector<QPoint> side = threadPixelsDrawn(*app.view);
  ASSERT_GT(side.size(), 20u) << "the thread is drawn in the side view";
  double n = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (const QPoint& p : side) {
    n += 1.0;
    sx += p.x();
    sy += p.y();
    sxx += static_cast<double>(p.x()) * p.x();
    sxy += static_cast<double>(p.x()) * p.y();
  }
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  const double offset = (sy - slope * sx) / n;
  const auto threadRowAt = [&](int x) { return qRound(offset + slope * x); };

  // over the thread (top view), 0.3 mm under it (side view), and over it again
  app.press(Qt::Key_1);
  const auto tip = [&] { return scissorsTipDrawn(app); };
  app.dragUntil(tip, [&] { return cutAt; });
  app.press(Qt::Key_3);
  app.dragUntil(tip, [&] { return QPoint(tip().x(), threadRowAt(tip().x()) + qRound(0.3 * pixelsPerMm)); });
  app.press(Qt::Key_1);
  app.dragUntil(tip, [&] { return cutAt; });
  ASSERT_TRUE(app.drawn().scissors[1].present);
  EXPECT_EQ(app.drawn().scissors[1].closure, 0.0);

  // a right click closes the blades: the thread is cut, the needle keeps about 1.5 mm
  auto* cut = app.window->findChild<QLabel*>(QStringLiteral("attemptCut"));
  auto* tooShort = app.window->findChild<QLabel*>(QStringLiteral("attemptThreadTooShort"));
  ASSERT_NE(cut, nullptr);
  ASSERT_NE(tooShort, nullptr);
  EXPECT_FALSE(cut->isVisible());
  QTest::mouseClick(app.view, Qt::RightButton, {}, QPoint(app.view->width() / 2, app.view->height() / 2));
  ASSERT_TRUE(QTest::qWaitFor([&] { return cut->isVisible(); }, 20000)) << "the page reports the cut";
  EXPECT_TRUE(QTest::qWaitFor([&] { return tooShort->isVisible(); }, 20000)) << "the page warns: too short to tie";

  std::vector<sim::SceneEvent> cuts;
  for (const sim::SceneEvent& e : app.attempt->runner()->events())
    if (e.kind == sim::SceneEventKind::ThreadCut) cuts.push_back(e);
  ASSERT_EQ(cuts.size(), 1u);
  EXPECT_EQ(cuts[0].hand, 1);
  // no stitch on either side of the cut: the page says so rather than give a length
  EXPECT_EQ(cuts[0].value, -1.0);
  EXPECT_EQ(cut->text(), AttemptPage::tr("The scissors cut the thread: no stitch holds it on either side of the cut."));
  double kept = -1.0;
  for (const sim::SceneEvent& e : app.attempt->runner()->events())
    if (e.kind == sim::SceneEventKind::ThreadTooShort) kept = e.value;
  EXPECT_NEAR(kept, 1.5, 0.4);
  EXPECT_TRUE(tooShort->text().contains(NumberFormat::value(kept, "mm"))) << tooShort->text().toStdString();

  // finished, the attempt's stored recording replays to the same cut
  const sim::SceneDef def = *app.attempt->runner()->sceneDef();
  const AttemptResult result = app.finish();
  ASSERT_TRUE(result.stored);
  const QList<assessment::Trainee> people = assessment::PeopleStore(app.history).trainees();
  ASSERT_EQ(people.size(), 1);
  const std::optional<assessment::AttemptDetail> detail =
      assessment::readAttemptDetail(app.history, {people[0].id, assessment::Role::Trainee}, result.attemptId);
  ASSERT_TRUE(detail.has_value());
  sim::Recording recording;
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(detail->recording.constData());
  ASSERT_TRUE(sim::decodeRecording(std::span(bytes, static_cast<std::size_t>(detail->recording.size())), recording).ok());
  sim::Scene replay(def);
  for (const sim::InputFrame& f : recording.frames) replay.step(f);
  std::vector<sim::SceneEvent> replayed;
  for (const sim::SceneEvent& e : replay.events())
    if (e.kind == sim::SceneEventKind::ThreadCut) replayed.push_back(e);
  ASSERT_EQ(replayed.size(), 1u);
  EXPECT_EQ(replayed[0].index, cuts[0].index);
  EXPECT_EQ(replayed[0].step, cuts[0].step);
}

}  // namespace
}  // namespace microsim::gui
