// The eyepiece's field stop without GL: a circle as wide as the area's smaller side, centred on
// it, and the mask over everything outside it, from the circle to past the corners.
#include "gui/render/eyepiece_pass.h"

#include <gtest/gtest.h>

#include <cmath>

namespace microsim::gui {
namespace {

TEST(EyepieceField, IsACircleAsWideAsTheSmallerSideCentredOnTheArea) {
  const EyepieceField field = eyepieceField(QRect(640, 0, 640, 800));
  EXPECT_DOUBLE_EQ(field.centre.x(), 960.0);
  EXPECT_DOUBLE_EQ(field.centre.y(), 400.0);
  EXPECT_FLOAT_EQ(field.radius, 320.0f);
  EXPECT_GT(field.edge, 0.0f);
  EXPECT_LT(field.edge, 0.2f * field.radius);
}

TEST(EyepieceField, TheMaskCoversFromTheCircleToPastTheCorners) {
  const QRect area(0, 0, 1280, 800);
  const std::vector<float> ring = fieldMaskTriangles(area, 64);
  ASSERT_EQ(ring.size(), 64u * 6u * 2u);
  float nearest = 1e9f;
  float farthest = 0.0f;
  for (std::size_t i = 0; i < ring.size(); i += 2) {
    // back from normalised device coordinates to pixels from the area's centre
    const float r = std::hypot(ring[i] * 640.0f, ring[i + 1] * 400.0f);
    nearest = std::min(nearest, r);
    farthest = std::max(farthest, r);
  }
  EXPECT_NEAR(nearest, 400.0f, 1e-2f) << "the mask begins at the field stop's circle";
  EXPECT_GT(farthest * std::cos(3.14159265f / 64.0f), std::hypot(640.0f, 400.0f)) << "and ends past the corners";
}

}  // namespace
}  // namespace microsim::gui
