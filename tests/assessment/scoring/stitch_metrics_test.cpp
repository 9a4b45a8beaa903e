// Per-stitch metrics on hand-made passages: pairing through both ends, bite symmetry, the
// spacing to the previous stitch across 0°, and the triangulation of the first three.
#include "microsim/assessment/scoring/stitch_metrics.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace microsim::assessment;

PierceMetrics passage(int end, double bite, double around, bool full = true) {
  PierceMetrics p;
  p.vessel = end;
  p.object = 0;
  p.end = end;
  p.biteMm = bite;
  p.circumferenceDeg = around;
  p.fullThickness = full;
  return p;
}

TEST(StitchMetrics, TwoPassagesThroughBothEndsAreOneStitch) {
  const std::vector<StitchMetrics> s =
      stitchMetrics({passage(0, 0.30, 350.0), passage(1, 0.22, 10.0)});
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].first, 0);
  EXPECT_EQ(s[0].second, 1);
  EXPECT_NEAR(s[0].symmetryMm, 0.08, 1e-12);
  EXPECT_NEAR(s[0].positionDeg, 0.0, 1e-9);  // the circular mean of 350° and 10°
  EXPECT_TRUE(std::isnan(s[0].spacingDeg));
  EXPECT_TRUE(s[0].fullThickness);
}

TEST(StitchMetrics, APassageWithoutItsPartnerIsSkippedAndSpacingIsTheShorterArc) {
  const std::vector<StitchMetrics> s =
      stitchMetrics({passage(0, 0.2, 30.0), passage(0, 0.2, 20.0), passage(1, 0.2, 20.0, false),
                     passage(0, 0.2, 300.0), passage(1, 0.2, 300.0)});
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].first, 1);
  EXPECT_FALSE(s[0].fullThickness);
  EXPECT_EQ(s[1].first, 3);
  EXPECT_NEAR(s[1].spacingDeg, 80.0, 1e-9);
}

TEST(StitchMetrics, TriangulationMeasuresTheWorstArcAgainst120Degrees) {
  std::vector<StitchMetrics> s(3);
  s[0].positionDeg = 0.0;
  s[1].positionDeg = 120.0;
  s[2].positionDeg = 240.0;
  EXPECT_NEAR(*triangulationErrorDeg(s), 0.0, 1e-12);
  s[1].positionDeg = 100.0;
  s[2].positionDeg = 250.0;  // arcs 100, 150, 110
  EXPECT_NEAR(*triangulationErrorDeg(s), 30.0, 1e-12);
  s.pop_back();
  EXPECT_FALSE(triangulationErrorDeg(s).has_value());
}

TEST(StitchMetrics, AngularDistanceWrapsAroundTheCircle) {
  EXPECT_DOUBLE_EQ(angularDistanceDeg(350.0, 10.0), 20.0);
  EXPECT_DOUBLE_EQ(angularDistanceDeg(0.0, 180.0), 180.0);
  EXPECT_DOUBLE_EQ(angularDistanceDeg(90.0, 90.0), 0.0);
}

}  // namespace
