// The opened vessel: angles round the vessel run across the wall from 0° at its left edge to
// 360° at its right, each error is marked at its angle and numbered, labels stay readable
// where stitches crowd, and errors with no angle are named rather than dropped.
#include "gui/pages/opened_vessel_image.h"

#include "i18n/end_product_words.h"

#include <QColor>
#include <QImage>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace microsim::gui {
namespace {

using assessment::EndProductError;
using assessment::EndProductErrorKind;

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
const QSize kSize(460, 300);

assessment::PierceMetrics passage(double angleDeg, int end, double biteWalls = 2.5) {
  assessment::PierceMetrics p;
  p.vessel = 0;
  p.object = 0;
  p.end = end;
  p.circumferenceDeg = angleDeg;
  p.biteWalls = biteWalls;
  p.fullThickness = true;
  return p;
}

// stitches at the given angles, each a passage through end 0 then end 1 a little apart
OpenedVessel stitchesAt(const std::vector<double>& angles) {
  OpenedVessel v;
  for (std::size_t s = 0; s < angles.size(); ++s) {
    v.passages.push_back(passage(angles[s], 0));
    v.passages.push_back(passage(std::fmod(angles[s] + 3.0, 360.0), 1));
    assessment::StitchMetrics st;
    st.first = int(2 * s);
    st.second = int(2 * s + 1);
    st.positionDeg = angles[s] + 1.5;
    v.stitches.push_back(st);
  }
  return v;
}

EndProductError error(EndProductErrorKind kind, double angleDeg, int passage = -1,
                      int stitch = -1) {
  EndProductError e;
  e.kind = kind;
  e.angleDeg = angleDeg;
  e.passage = passage;
  e.stitch = stitch;
  return e;
}

TEST(OpenedVesselImage, AnglesRunAcrossTheWallFromZeroToThreeSixty) {
  OpenedVessel v = stitchesAt({270.0});
  v.errors = {error(EndProductErrorKind::UnequalSpacing, 90.0),
              error(EndProductErrorKind::ObliqueStitch, 180.0, -1, 0),
              error(EndProductErrorKind::BackWallStitch, 0.0),
              error(EndProductErrorKind::WideBite, 270.0, 0, 0)};
  const OpenedVesselLayout layout = OpenedVesselImage::layOut(v, kSize);
  const QRectF& wall = layout.wall;
  ASSERT_GT(wall.width(), 300.0);
  ASSERT_EQ(layout.marks.size(), 4u);
  // an error at 90° lies a quarter of the way across, on the suture line
  EXPECT_NEAR(layout.marks[0].at.x(), wall.left() + wall.width() / 4, 1e-9);
  EXPECT_NEAR(layout.marks[0].at.y(), layout.sutureLineY, 1e-9);
  EXPECT_NEAR(layout.marks[1].at.x(), wall.left() + wall.width() / 2, 1e-9);
  EXPECT_NEAR(layout.marks[2].at.x(), wall.left(), 1e-9);
  // one on a passage sits on it: end 1 above the suture line, end 2 below
  EXPECT_NEAR(layout.marks[3].at.x(), wall.left() + wall.width() * 3 / 4, 1e-9);
  EXPECT_EQ(layout.marks[3].at, layout.passages[0]);
  EXPECT_LT(layout.passages[0].y(), layout.sutureLineY);
  EXPECT_GT(layout.passages[1].y(), layout.sutureLineY);
  EXPECT_NEAR(layout.sutureLineY, wall.center().y(), 1e-9);
  // numbered in error order
  EXPECT_EQ(layout.marks[0].label, QStringLiteral("1"));
  EXPECT_EQ(layout.marks[3].label, QStringLiteral("4"));
  // the circumference is labelled at 0°, 90°, 180°, 270° and 360°, each over its place
  ASSERT_EQ(layout.axisLabels.size(), 5u);
  EXPECT_EQ(layout.axisLabels[1].text, QStringLiteral("90°"));
  EXPECT_NEAR(layout.axisLabels[1].rect.center().x(), wall.left() + wall.width() / 4, 0.5);
  EXPECT_NEAR(layout.axisLabels[4].rect.center().x(), wall.right(), 0.5);
  // the walls are named under the wall: front at 45° and 315°, back at 180°
  ASSERT_GE(layout.wallNames.size(), 3u);
  EXPECT_EQ(layout.wallNames[0].text, QStringLiteral("front wall"));
  EXPECT_EQ(layout.wallNames[1].text, QStringLiteral("back wall"));
  EXPECT_NEAR(layout.wallNames[1].rect.center().x(), wall.center().x(), 1.0);
  EXPECT_GE(layout.wallNames[1].rect.top(), wall.bottom());
}

// a stitch across the 0°/360° seam runs the short way: out at the right edge, in at the left
TEST(OpenedVesselImage, AThreadAcrossTheSeamGoesTheShortWayRound) {
  const OpenedVesselLayout across = OpenedVesselImage::layOut(stitchesAt({358.0}), kSize);
  ASSERT_EQ(across.threads.size(), 2u);
  EXPECT_EQ(across.threads[0].p1(), across.passages[0]);
  EXPECT_GT(across.threads[0].p2().x(), across.wall.right());
  EXPECT_LT(across.threads[1].p1().x(), across.wall.left());
  EXPECT_EQ(across.threads[1].p2(), across.passages[1]);
  ASSERT_EQ(across.stitchLabels.size(), 1u);
  EXPECT_TRUE(across.stitchLabels[0].at.x() < across.wall.left() + 10 ||
              across.stitchLabels[0].at.x() > across.wall.right() - 10);
  const OpenedVesselLayout within = OpenedVesselImage::layOut(stitchesAt({100.0}), kSize);
  ASSERT_EQ(within.threads.size(), 1u);
  EXPECT_EQ(within.threads[0].p2(), within.passages[1]);
}

TEST(OpenedVesselImage, TwoErrorsOnOnePassageStackAwayFromTheLine) {
  OpenedVessel v = stitchesAt({200.0});
  v.errors = {error(EndProductErrorKind::BackWallStitch, 200.0, 0, 0),
              error(EndProductErrorKind::PartialThicknessBite, 200.0, 0, 0)};
  const OpenedVesselLayout layout = OpenedVesselImage::layOut(v, kSize);
  ASSERT_EQ(layout.marks.size(), 2u);
  EXPECT_EQ(layout.marks[0].at.x(), layout.marks[1].at.x());
  EXPECT_LT(layout.marks[1].at.y(), layout.marks[0].at.y());  // end 1 is above: further up
}

// eight stitches crowded into 40° with three errors on most passages: every number and
// stitch label inside the wall, over no other label, marker or passage
TEST(OpenedVesselImage, LabelsOfCrowdedErrorsNeitherOverlapNorLeaveTheWall) {
  OpenedVessel v = stitchesAt({350.0, 355.0, 0.0, 5.0, 10.0, 15.0, 20.0, 25.0});
  for (int p = 0; p < int(v.passages.size()); p += 3) {
    const double angle = v.passages[std::size_t(p)].circumferenceDeg;
    v.errors.push_back(error(EndProductErrorKind::BackWallStitch, angle, p, p / 2));
    v.errors.push_back(error(EndProductErrorKind::WideBite, angle, p, p / 2));
  }
  v.errors.push_back(error(EndProductErrorKind::UnequalSpacing, 10.0));
  const OpenedVesselLayout layout = OpenedVesselImage::layOut(v, kSize);

  std::vector<QRectF> labels;
  for (const OpenedVesselLayout::Mark& m : layout.marks) labels.push_back(m.labelRect);
  for (const OpenedVesselLayout::StitchLabel& s : layout.stitchLabels)
    labels.push_back(s.labelRect);
  ASSERT_EQ(labels.size(), v.errors.size() + v.stitches.size());
  std::vector<QRectF> marks;
  for (const OpenedVesselLayout::Mark& m : layout.marks)
    marks.emplace_back(m.at - QPointF(5, 5), QSizeF(10, 10));
  for (const QPointF& p : layout.passages) marks.emplace_back(p - QPointF(3, 3), QSizeF(6, 6));
  for (std::size_t i = 0; i < labels.size(); ++i) {
    EXPECT_TRUE(layout.wall.contains(labels[i])) << "label " << i;
    EXPECT_GT(labels[i].width(), 5.0);
    for (std::size_t j = i + 1; j < labels.size(); ++j)
      EXPECT_FALSE(labels[i].intersects(labels[j])) << "labels " << i << " and " << j;
    for (std::size_t k = 0; k < marks.size(); ++k)
      EXPECT_FALSE(labels[i].intersects(marks[k])) << "label " << i << " over mark " << k;
  }
  // the legend's entries lie under the wall and its names, apart
  for (std::size_t i = 0; i < layout.legend.size(); ++i) {
    EXPECT_GE(layout.legend[i].text.rect.top(), layout.wallNames[0].rect.bottom());
    for (std::size_t j = i + 1; j < layout.legend.size(); ++j)
      EXPECT_FALSE(layout.legend[i].text.rect.intersects(layout.legend[j].text.rect));
  }
  for (std::size_t i = 0; i < layout.axisLabels.size(); ++i)
    for (std::size_t j = i + 1; j < layout.axisLabels.size(); ++j)
      EXPECT_FALSE(layout.axisLabels[i].rect.intersects(layout.axisLabels[j].rect));
}

// the final scene's lapses (sim/scene/end_state_check.h) have an angle and no passage: each on
// the suture line at its angle, in the legend in its own words
TEST(OpenedVesselImage, TheFinalScenesLapsesAreMarkedOnTheSutureLineAtTheirAngle) {
  OpenedVessel v = stitchesAt({45.0});
  v.errors = {error(EndProductErrorKind::OverTightStitch, 45.0),
              error(EndProductErrorKind::ThreadInLumen, 180.0),
              error(EndProductErrorKind::LargeEdgeOverlap, 270.0)};
  const OpenedVesselLayout layout = OpenedVesselImage::layOut(v, kSize);
  const QRectF& wall = layout.wall;
  ASSERT_EQ(layout.marks.size(), 3u);
  EXPECT_TRUE(layout.unlocated.empty());
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(layout.marks[i].at.x(), wall.left() + wall.width() * v.errors[i].angleDeg / 360.0,
                1e-9)
        << i;
    EXPECT_NEAR(layout.marks[i].at.y(), layout.sutureLineY, 1e-9) << i;
  }
  ASSERT_EQ(layout.legend.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(layout.legend[i].kind, v.errors[i].kind);
    EXPECT_EQ(layout.legend[i].text.text, i18n::EndProductWords::kind(v.errors[i].kind));
    EXPECT_FALSE(layout.legend[i].text.text.isEmpty());
  }
}

TEST(OpenedVesselImage, ErrorsWithNoAngleAreNamedUnderTheLegend) {
  OpenedVessel v = stitchesAt({45.0});
  v.errors = {error(EndProductErrorKind::WideBite, 45.0, 0, 0),
              error(EndProductErrorKind::WallTear, kNan),
              error(EndProductErrorKind::SutureLineDisruption, kNan)};
  const OpenedVesselLayout layout = OpenedVesselImage::layOut(v, kSize);
  ASSERT_EQ(layout.marks.size(), 1u);
  EXPECT_EQ(layout.unlocated, (std::vector<int>{1, 2}));
  const QString& text = layout.unlocatedText.text;
  EXPECT_TRUE(text.contains(i18n::EndProductWords::kind(EndProductErrorKind::WallTear) +
                            QStringLiteral(" (2)")))
      << text.toStdString();
  EXPECT_TRUE(text.contains(i18n::EndProductWords::kind(EndProductErrorKind::SutureLineDisruption) +
                            QStringLiteral(" (3)")))
      << text.toStdString();
  EXPECT_TRUE(QRectF(QPointF(0, 0), QSizeF(kSize)).contains(layout.unlocatedText.rect));
  // the legend names only the kinds drawn
  ASSERT_EQ(layout.legend.size(), 1u);
  EXPECT_EQ(layout.legend[0].kind, EndProductErrorKind::WideBite);
  EXPECT_EQ(layout.legend[0].text.text, i18n::EndProductWords::kind(EndProductErrorKind::WideBite));
}

TEST(OpenedVesselImage, DrawsTheBackWallShadedAndEachMarkerInItsColour) {
  OpenedVessel v = stitchesAt({180.0});
  v.errors = {error(EndProductErrorKind::BackWallStitch, 180.0, 0, 0)};
  const QImage image = OpenedVesselImage::draw(v, kSize);
  ASSERT_EQ(image.size(), kSize);
  const OpenedVesselLayout layout = OpenedVesselImage::layOut(v, kSize);
  const QRectF& wall = layout.wall;
  // the back wall (90–270°) darker than the front (0–90°), away from every mark
  const QColor front =
      image.pixelColor(QPointF(wall.left() + wall.width() / 16, wall.top() + 3).toPoint());
  const QColor back =
      image.pixelColor(QPointF(wall.left() + wall.width() * 5 / 16, wall.top() + 3).toPoint());
  EXPECT_LT(back.lightness(), front.lightness());
  // the back-wall marker's purple round its passage
  int purple = 0;
  const QPointF at = layout.marks[0].at;
  for (int y = int(at.y()) - 8; y <= int(at.y()) + 8; ++y)
    for (int x = int(at.x()) - 8; x <= int(at.x()) + 8; ++x) {
      const QColor c = image.pixelColor(x, y);
      if (c.red() > 80 && c.red() < 140 && c.green() < 60 && c.blue() > 120) ++purple;
    }
  EXPECT_GT(purple, 5);
  // for paper: the same drawing with more pixels to each unit
  const QImage sharp = OpenedVesselImage::draw(v, kSize, 3.0);
  EXPECT_EQ(sharp.size(), kSize * 3);
  EXPECT_EQ(sharp.devicePixelRatio(), 3.0);
  const QPointF inBack(wall.left() + wall.width() * 5 / 16, wall.top() + 3);
  EXPECT_EQ(sharp.pixelColor((inBack * 3).toPoint()).rgb(), back.rgb());
}

}  // namespace
}  // namespace microsim::gui
