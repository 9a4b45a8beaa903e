// The pierce diagram's labels: pierces of one stitch lie a few pixels apart, and their
// labels must still each be readable, inside the image and over no other label or dot.
#include "gui/pages/pierce_image.h"

#include <QColor>
#include <QImage>

#include <gtest/gtest.h>

#include <cmath>

namespace microsim::gui {
namespace {

// two vessel ends meeting at x = 3 mm, as the shipped anastomosis scene lays them out
std::vector<sim::VesselDef> facingVessels() {
  sim::VesselDef left;
  left.origin = sim::Vec3(0.0, 0.0, 0.0);
  left.direction = sim::Vec3::UnitX();
  left.length = 2.9;
  sim::VesselDef right = left;
  right.origin = sim::Vec3(6.0, 0.0, 0.0);
  right.direction = -sim::Vec3::UnitX();
  return {left, right};
}

// `count` pierces crowded around the gap, entries and exits alternating, 0.03 mm apart
std::vector<sim::PierceEvent> crowdedPierces(int count) {
  std::vector<sim::PierceEvent> pierces;
  for (int i = 0; i < count; ++i) {
    sim::PierceEvent p;
    p.entry = i % 2 == 0;
    p.point = sim::Vec3(2.88 + 0.03 * i, 0.0, 0.45 - 0.01 * (i % 3));
    p.tangent = sim::Vec3(std::sin(0.3 * i), 0.0, -std::cos(0.3 * i));
    p.angleDeg = 40.0 + 3.3 * i;
    pierces.push_back(p);
  }
  return pierces;
}

TEST(PierceImage, LabelsOfCrowdedPiercesNeitherOverlapNorLeaveTheImage) {
  const QSize size(420, 260);
  for (const int count : {2, 4, 8}) {
    const std::vector<sim::PierceEvent> pierces = crowdedPierces(count);
    const std::vector<QRectF> labels = pierceLabelRects(facingVessels(), pierces, size);
    ASSERT_EQ(labels.size(), pierces.size());
    const QRectF image(QPointF(0, 0), QSizeF(size));
    for (std::size_t i = 0; i < labels.size(); ++i) {
      EXPECT_TRUE(image.contains(labels[i])) << count << " pierces, label " << i + 1;
      EXPECT_GT(labels[i].width(), 10.0);
      for (std::size_t j = i + 1; j < labels.size(); ++j)
        EXPECT_FALSE(labels[i].intersects(labels[j])) << count << " pierces, labels " << i + 1 << " and " << j + 1;
    }
  }
}

TEST(PierceImage, DrawsTheVesselsAndEachPierceInItsColour) {
  const QImage image = drawPierceAngles(facingVessels(), crowdedPierces(2), QSize(420, 260));
  ASSERT_EQ(image.size(), QSize(420, 260));
  int red = 0, blue = 0;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      const QColor c = image.pixelColor(x, y);
      if (c == QColor(0xd3, 0x2f, 0x2f)) ++red;
      if (c == QColor(0x19, 0x5f, 0xc0)) ++blue;
    }
  }
  EXPECT_GT(red, 10) << "the entry's dot and line";
  EXPECT_GT(blue, 10) << "the exit's dot and line";
}

}  // namespace
}  // namespace microsim::gui
