// Per-pierce metrics on hand-made pierce events with known answers: entry/exit pairing,
// full thickness vs partial, back-wall catches, bites in wall thicknesses and the angle
// around the circumference.
#include "microsim/assessment/scoring/pierce_metrics.h"

#include "support/severed_vessel.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace microsim::assessment;
using microsim::sim::PierceEvent;
using microsim::sim::Vec3;
using microsim::sim::VesselSurface;
using microsim::sim::VesselWall;

using microsim::testing::severedVessel;

PierceEvent pierce(bool entry, int end, VesselSurface s, double angle, double bite,
                   const Vec3& point, VesselWall wall = VesselWall::Front) {
  PierceEvent p;
  p.entry = entry;
  p.vessel = end;
  p.end = end;
  p.surface = s;
  p.angleDeg = angle;
  p.biteMm = bite;
  p.point = point;
  p.wall = wall;
  return p;
}

TEST(PierceMetrics, CircumferentialAngleIsZeroTowardTheCameraAndTurnsRightHanded) {
  const Attempt a = severedVessel();
  const VesselGeometry& g = a.vessels[0];
  EXPECT_NEAR(circumferentialAngleDeg(g, Vec3(-0.5, 0.0, 0.5)), 0.0, 1e-9);
  // x × z = −y: a quarter turn about +x takes +z to −y
  EXPECT_NEAR(circumferentialAngleDeg(g, Vec3(-0.5, -0.5, 0.0)), 90.0, 1e-9);
  EXPECT_NEAR(circumferentialAngleDeg(g, Vec3(-0.5, 0.0, -0.5)), 180.0, 1e-9);
  EXPECT_NEAR(circumferentialAngleDeg(g, Vec3(-0.5, 0.5, 0.0)), 270.0, 1e-9);
  EXPECT_NEAR(circumferentialAngleDeg(g, Vec3(-0.5, 0.5, 0.5)), 315.0, 1e-9);
}

TEST(PierceMetrics, AnEntryAndExitThroughTheWallIsOneFullThicknessPassage) {
  Attempt a = severedVessel();
  a.pierces = {pierce(true, 0, VesselSurface::Outer, 10.0, 0.25, Vec3(-0.5, 0.0, 0.5)),
               pierce(false, 0, VesselSurface::Inner, 20.0, 0.24, Vec3(-0.5, 0.0, 0.4)),
               pierce(true, 1, VesselSurface::Inner, 30.0, 0.20, Vec3(0.45, -0.4, 0.0)),
               pierce(false, 1, VesselSurface::Outer, 40.0, 0.21, Vec3(0.45, -0.5, 0.0))};
  a.pierces[2].time = 1.5;
  const std::vector<PierceMetrics> m = pierceMetrics(a);
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m[0].entry, 0);
  EXPECT_EQ(m[0].exit, 1);
  EXPECT_DOUBLE_EQ(m[0].entryAngleDeg, 10.0);
  EXPECT_DOUBLE_EQ(m[0].exitAngleDeg, 20.0);
  EXPECT_DOUBLE_EQ(m[0].biteMm, 0.25);
  EXPECT_NEAR(m[0].biteWalls, 2.5, 1e-12);
  EXPECT_NEAR(m[0].circumferenceDeg, 0.0, 1e-9);
  EXPECT_TRUE(m[0].fullThickness);
  EXPECT_FALSE(m[0].backWall);
  EXPECT_EQ(m[1].entry, 2);
  EXPECT_EQ(m[1].exit, 3);
  EXPECT_EQ(m[1].end, 1);
  EXPECT_EQ(m[1].object, 0);
  EXPECT_DOUBLE_EQ(m[1].time, 1.5);
  EXPECT_NEAR(m[1].circumferenceDeg, 90.0, 1e-9);
  EXPECT_TRUE(m[1].fullThickness);
}

TEST(PierceMetrics, InAndOutOfTheSameSurfaceIsPartialAndAMissingExitIsNaN) {
  Attempt a = severedVessel();
  a.pierces = {pierce(true, 0, VesselSurface::Outer, 5.0, 0.2, Vec3(-0.5, 0.0, 0.5)),
               pierce(false, 0, VesselSurface::Outer, 5.0, 0.1, Vec3(-0.4, 0.0, 0.5)),
               pierce(true, 0, VesselSurface::CutEnd, 5.0, 0.0, Vec3(-0.25, 0.0, 0.45))};
  const std::vector<PierceMetrics> m = pierceMetrics(a);
  ASSERT_EQ(m.size(), 2u);
  EXPECT_FALSE(m[0].fullThickness);
  EXPECT_EQ(m[1].exit, -1);
  EXPECT_TRUE(std::isnan(m[1].exitAngleDeg));
  EXPECT_FALSE(m[1].fullThickness);
}

TEST(PierceMetrics, AnEntryOnTheBackWallIsACatchAndOtherTissueIsSkipped) {
  Attempt a = severedVessel();
  PierceEvent other = pierce(true, 0, VesselSurface::NotAVessel, 0.0, 0.0, Vec3::Zero());
  other.vessel = -1;
  a.pierces = {other,
               pierce(true, 1, VesselSurface::Inner, 0.0, 0.2, Vec3(0.5, 0.0, -0.4), VesselWall::Back),
               pierce(false, 1, VesselSurface::Outer, 0.0, 0.2, Vec3(0.5, 0.0, -0.5), VesselWall::Back)};
  const std::vector<PierceMetrics> m = pierceMetrics(a);
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].entry, 1);
  EXPECT_TRUE(m[0].backWall);
  EXPECT_NEAR(m[0].circumferenceDeg, 180.0, 1e-9);
}

TEST(PierceMetrics, AnExitClosesTheLatestOpenPassageOfItsOwnVessel) {
  Attempt a = severedVessel();
  a.pierces = {pierce(true, 0, VesselSurface::Outer, 1.0, 0.2, Vec3(-0.5, 0.0, 0.5)),
               pierce(true, 1, VesselSurface::Outer, 2.0, 0.2, Vec3(0.5, 0.0, 0.5)),
               pierce(false, 0, VesselSurface::Inner, 3.0, 0.2, Vec3(-0.5, 0.0, 0.4))};
  const std::vector<PierceMetrics> m = pierceMetrics(a);
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m[0].exit, 2);
  EXPECT_EQ(m[1].exit, -1);
}

}  // namespace
