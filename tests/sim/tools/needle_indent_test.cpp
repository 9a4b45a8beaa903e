// The needle tip's dent on one face (tools/needle_indent.h) and the faces that move over a
// standing tip (PierceDetector::passedOver, tools/needle.h).
#include "microsim/sim/tools/needle_indent.h"

#include "microsim/sim/tools/needle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace microsim::sim::tools {
namespace {

// one face in the plane z = 0, its normal +z (out of the material below it), and a second
// face sharing its corner 2
SpringModel twoFacesInAPlane() {
  SpringModel m;
  m.addNode(Vec3(0.0, 0.0, 0.0));
  m.addNode(Vec3(1.0, 0.0, 0.0));
  m.addNode(Vec3(0.0, 1.0, 0.0));
  m.addNode(Vec3(-1.0, 1.0, 0.0));
  m.addNode(Vec3(-1.0, 2.0, 0.0));
  m.addLink(0, 1, 1.0);
  m.addTriangle(0, 1, 2);
  m.addTriangle(2, 4, 3);
  m.finalize();
  return m;
}

FaceCrossing entryAtCentre() {
  FaceCrossing c;
  c.face = 0;
  c.barycentric = Vec3(1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0);
  c.point = Vec3(1.0 / 3.0, 1.0 / 3.0, 0.0);
  c.normal = Vec3::UnitZ();
  c.entry = true;
  return c;
}

TEST(NeedleIndent, AnEntryPressesFromTheFrontAndAnExitFromBehind) {
  EXPECT_TRUE(beginIndentation(entryAtCentre(), 0.0).side.isApprox(Vec3::UnitZ()));
  FaceCrossing exit = entryAtCentre();
  exit.entry = false;
  EXPECT_TRUE(beginIndentation(exit, 0.0).side.isApprox(-Vec3::UnitZ()));
}

TEST(NeedleIndent, TheForceIsTheSpringsPullAlongTheTipsTravel) {
  const SpringModel m = twoFacesInAPlane();
  const Indentation in = beginIndentation(entryAtCentre(), 0.0);
  Points x = m.restPositions();
  const double k = 1000.0;
  // the tip 0.01 mm below the face's point, travelling down and sideways at 45°
  const Vec3 tip = in.touch.point - Vec3(0.0, 0.0, 0.01);
  const Vec3 travel = Vec3(1.0, 0.0, -1.0).normalized();
  EXPECT_NEAR(indentationForce(m, x, in, tip, travel, k), k * 0.01 / std::sqrt(2.0), 1e-12);
  EXPECT_FALSE(tipWithdrawn(m, x, in, tip));

  // the spring pulls the face's point onto the tip
  const PointSpring s = indentationSpring(m, in, tip, k);
  EXPECT_FALSE(s.oneSided());
  EXPECT_TRUE(pointSpringOffset(s, x).isApprox(in.touch.point - tip));

  // the face pushed down past the tip: the tip is back on its own side
  x.row(2).array() -= 0.02;
  EXPECT_TRUE(tipWithdrawn(m, x, in, tip));
  EXPECT_LT(indentationForce(m, x, in, tip, travel, k), 0.0);
}

// After a solve the spring holds the face's point on the tip to within the solve's tolerance,
// on either side of it; a tip still beyond where it first touched is still pressing, and only
// a face clearly past the tip, or a tip back past the first touch, ends the dent.
TEST(NeedleIndent, AFaceHeldOnTheTipWithinTheSolvesToleranceIsStillPressed) {
  const SpringModel m = twoFacesInAPlane();
  const Indentation in = beginIndentation(entryAtCentre(), 0.1);
  Points x = m.restPositions();
  // the face dented 0.02 mm, its point a hair (1e-9 mm) deeper than the tip
  x.row(2).array() -= 0.02;
  const Vec3 tip = in.touch.point - Vec3(0.0, 0.0, 0.02 - 1e-9);
  EXPECT_FALSE(tipWithdrawn(m, x, in, tip));
  // the tip drawn back above where it first touched: it no longer presses
  EXPECT_TRUE(tipWithdrawn(m, x, in, in.touch.point + Vec3(0.0, 0.0, 1e-6)));
}

TEST(NeedleIndent, AWallCarriedItsThicknessPastTheTouchIsPuncturedWithoutTheForce) {
  const SpringModel m = twoFacesInAPlane();
  const Indentation in = beginIndentation(entryAtCentre(), 0.1);
  Points x = m.restPositions();
  const double k = 1000.0;
  const Vec3 down = -Vec3::UnitZ();
  // the whole face rides on the tip (no dent, no force), 0.09 then 0.1 mm below the touch
  x.row(2).array() -= 0.09;
  Vec3 tip = in.touch.point + 0.09 * down;
  EXPECT_NEAR(indentationDepth(in, tip), 0.09, 1e-12);
  EXPECT_NEAR(indentationForce(m, x, in, tip, down, k), 0.0, 1e-9);
  EXPECT_FALSE(punctured(m, x, in, tip, down, k, 400.0));
  x.row(2).array() -= 0.01;
  tip = in.touch.point + 0.1 * down;
  EXPECT_TRUE(punctured(m, x, in, tip, down, k, 400.0));
  // without a depth the force alone decides: a dent of 0.4 mm at 1000 g/s² is 400 µN
  const Indentation byForce = beginIndentation(entryAtCentre(), 0.0);
  EXPECT_FALSE(punctured(m, x, byForce, tip, down, k, 400.0));
  EXPECT_TRUE(punctured(m, m.restPositions(), byForce, in.touch.point + 0.4 * down, down, k, 400.0));
}

TEST(NeedleIndent, FacesAroundAFaceShareACornerWithIt) {
  const SpringModel m = twoFacesInAPlane();
  EXPECT_EQ(facesAround(m, 0), (std::vector<int>{0, 1}));
  EXPECT_EQ(facesAround(m, 1), (std::vector<int>{0, 1}));
}

TEST(NeedleIndent, AFaceMovedOverAStandingTipIsACrossingAndOneMovedBesideItIsNot) {
  const SpringModel m = twoFacesInAPlane();
  const Points before = m.restPositions();
  PierceDetector<collide::Aabb> detector(m, before);
  const Vec3 tip(0.25, 0.25, -0.05);

  // the first face moves down 0.1 mm past the tip below it: seen from the tissue, the tip left
  // the material through the face
  Points after = before;
  for (int c : m.triangles()[0]) after(2, c) -= 0.1;
  detector.maintain({0, 1, 2}, after);
  std::vector<FaceCrossing> out;
  detector.passedOver(m, before, after, tip, 0.2, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].face, 0);
  EXPECT_FALSE(out[0].entry);
  EXPECT_TRUE(out[0].point.isApprox(Vec3(0.25, 0.25, -0.1)));
  EXPECT_NEAR(out[0].barycentric.sum(), 1.0, 1e-12);

  // back up again: the tip goes in through its front
  detector.maintain({0, 1, 2}, before);
  detector.passedOver(m, after, before, tip, 0.2, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_TRUE(out[0].entry);

  // the same motion beside the tip (off the face's edge) crosses nothing
  detector.maintain({0, 1, 2}, after);
  detector.passedOver(m, before, after, Vec3(0.9, 0.9, -0.05), 0.2, out);
  EXPECT_TRUE(out.empty());
}

}  // namespace
}  // namespace microsim::sim::tools
