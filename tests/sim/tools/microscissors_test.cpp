// Microscissors (tools/microscissors.h): the blades cut each strand between them once, where
// they close on it; needle links are not cut; the cut-end and the needle's free thread are
// measured along the chain to the nearest anchor.
#include "microsim/sim/tools/microscissors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace microsim::sim::tools {
namespace {

/// A straight chain of `links` links of 0.1 mm along x, starting at x = x0, at height y = y0
/// and z = 0 (mm).
Points straightChain(int links, double x0, double y0) {
  Points x(3, links + 1);
  for (int i = 0; i <= links; ++i) x.col(i) = Vec3(x0 + 0.1 * i, y0, 0.0);
  return x;
}

/// Scissors whose blades lie in the x–z plane of the scene, pointing down −y, tip at `tip`:
/// tool x (back along the blades) = scene +y, tool y (the opening) = scene +x.
Eigen::Isometry3d bladesDownAt(const Vec3& tip) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  Eigen::Matrix3d r;
  r.col(0) = Vec3::UnitY();
  r.col(1) = Vec3::UnitX();
  r.col(2) = -Vec3::UnitZ();
  pose.linear() = r;
  pose.translation() = tip;
  return pose;
}

TEST(Microscissors, BladeTipsMeetAtTheToolTipWhenClosed) {
  ScissorsDef def;
  const auto closed = scissorsBladeTips(def, 1.0);
  EXPECT_NEAR(closed[0].norm(), 0.0, 1e-12);
  EXPECT_NEAR(closed[1].norm(), 0.0, 1e-12);
  const auto open = scissorsBladeTips(def, 0.0);
  const double theta = def.openingDeg * 3.14159265358979323846 / 180.0;
  EXPECT_NEAR(open[0].y(), def.bladeLength * std::sin(theta), 1e-12);
  EXPECT_NEAR(open[1].y(), -def.bladeLength * std::sin(theta), 1e-12);
}

TEST(Microscissors, BladePosesPutEachBladeTipAtItsTipAndEveryBladeOnThePivot) {
  ScissorsDef def;
  const Eigen::Isometry3d pose = bladesDownAt(Vec3(0.3, -0.2, 1.5));
  for (const double closure : {0.0, 0.4, 1.0}) {
    const auto blades = scissorsBladePoses(def, pose, closure);
    const auto tips = scissorsBladeTips(def, closure);
    for (std::size_t b = 0; b < 2; ++b) {
      // the blade frame's origin is the blade's tip, its (L, 0, 0) the pivot
      EXPECT_TRUE((blades[b] * Vec3::Zero()).isApprox(pose * tips[b], 1e-12)) << closure << " blade " << b;
      EXPECT_TRUE((blades[b] * Vec3(def.bladeLength, 0.0, 0.0)).isApprox(pose * Vec3(def.bladeLength, 0.0, 0.0), 1e-12));
    }
    // the lower blade is the upper one mirrored in the tool's y: its back faces away from the upper's
    const Vec3 upperBack = blades[0].linear() * Vec3::UnitY(), lowerBack = blades[1].linear() * Vec3::UnitY();
    EXPECT_NEAR(upperBack.dot(pose.linear() * Vec3::UnitY()), std::cos((1.0 - closure) * def.openingDeg * 3.14159265358979323846 / 180.0), 1e-12);
    EXPECT_NEAR(lowerBack.dot(pose.linear() * Vec3::UnitY()), -upperBack.dot(pose.linear() * Vec3::UnitY()), 1e-12);
  }
}

TEST(Microscissors, ClosingOnAStrandCutsItOnceWhereTheBladesMeet) {
  ScissorsDef def;
  // the thread runs along x at y = 0.2 (between the open blades, 0.2 mm behind the tip);
  // the tool axis crosses it at x = 1.05, in the middle of link 10 (nodes at 1.0 and 1.1)
  const Points chain = straightChain(30, 0.0, 0.2);
  const std::vector<std::uint8_t> alive(30, 1);
  const Eigen::Isometry3d pose = bladesDownAt(Vec3(1.05, 0.0, 0.0));
  const std::vector<ThreadCut> cuts = scissorsCuts(def, pose, 0.0, 1.0, chain, alive, 0, 0.01);
  ASSERT_EQ(cuts.size(), 1u);
  EXPECT_EQ(cuts[0].link, 10);
  EXPECT_NEAR(cuts[0].point.x(), 1.05, 1e-9);
  EXPECT_NEAR(cuts[0].point.y(), 0.2, 1e-9);
}

TEST(Microscissors, OnlyTheClosingThroughCutAtCuts) {
  ScissorsDef def;
  const Points chain = straightChain(30, 0.0, 0.2);
  const std::vector<std::uint8_t> alive(30, 1);
  const Eigen::Isometry3d pose = bladesDownAt(Vec3(1.05, 0.0, 0.0));
  EXPECT_TRUE(scissorsCuts(def, pose, 0.0, 0.5, chain, alive, 0, 0.01).empty());   // not yet closed
  EXPECT_TRUE(scissorsCuts(def, pose, 0.95, 1.0, chain, alive, 0, 0.01).empty());  // already closed
  EXPECT_TRUE(scissorsCuts(def, pose, 1.0, 0.0, chain, alive, 0, 0.01).empty());   // opening
}

TEST(Microscissors, AStrandOutsideTheBladesIsNotCut) {
  ScissorsDef def;
  const Eigen::Isometry3d pose = bladesDownAt(Vec3(1.05, 0.0, 0.0));
  const std::vector<std::uint8_t> alive(30, 1);
  // beyond the pivot (y > blade length), in front of the tip (y < 0), or above the blades
  EXPECT_TRUE(scissorsCuts(def, pose, 0.0, 1.0, straightChain(30, 0.0, def.bladeLength + 0.05), alive, 0, 0.01).empty());
  EXPECT_TRUE(scissorsCuts(def, pose, 0.0, 1.0, straightChain(30, 0.0, -0.05), alive, 0, 0.01).empty());
  Points above = straightChain(30, 0.0, 0.2);
  above.row(2).setConstant(def.bladeHalfThickness + 0.02);
  EXPECT_TRUE(scissorsCuts(def, pose, 0.0, 1.0, above, alive, 0, 0.01).empty());
}

TEST(Microscissors, TwoStrandsBetweenTheBladesAreBothCut) {
  ScissorsDef def;
  // a hairpin: out along y = 0.15 and back along y = 0.3, both strands between the blades
  Points chain(3, 41);
  for (int i = 0; i <= 20; ++i) chain.col(i) = Vec3(0.1 * i, 0.15, 0.0);
  for (int i = 21; i <= 40; ++i) chain.col(i) = Vec3(0.1 * (40 - i), 0.3, 0.0);
  const std::vector<std::uint8_t> alive(40, 1);
  const std::vector<ThreadCut> cuts = scissorsCuts(def, bladesDownAt(Vec3(1.05, 0.0, 0.0)), 0.0, 1.0, chain, alive, 0, 0.01);
  ASSERT_EQ(cuts.size(), 2u);
  EXPECT_EQ(cuts[0].link, 10);
  EXPECT_EQ(cuts[1].link, 29);
}

TEST(Microscissors, NeedleLinksAndBrokenLinksAreNotCut) {
  ScissorsDef def;
  const Points chain = straightChain(30, 0.0, 0.2);
  std::vector<std::uint8_t> alive(30, 1);
  const Eigen::Isometry3d pose = bladesDownAt(Vec3(1.05, 0.0, 0.0));
  // the open blades span links 8–12 of this strand: steel up to link 12 is not cut, and a
  // strand that turns to thread inside the blades is cut on its thread
  EXPECT_TRUE(scissorsCuts(def, pose, 0.0, 1.0, chain, alive, 13, 0.01).empty());
  const std::vector<ThreadCut> onThread = scissorsCuts(def, pose, 0.0, 1.0, chain, alive, 11, 0.01);
  ASSERT_EQ(onThread.size(), 1u);
  EXPECT_EQ(onThread[0].link, 11);
  for (int i = 8; i <= 12; ++i) alive[static_cast<std::size_t>(i)] = 0;
  EXPECT_TRUE(scissorsCuts(def, pose, 0.0, 1.0, chain, alive, 0, 0.01).empty());
}

TEST(Microscissors, TheCutEndIsMeasuredToTheNearestAnchor) {
  const Points chain = straightChain(30, 0.0, 0.0);
  std::vector<std::uint8_t> alive(30, 1);
  const ThreadCut cut{10, Vec3(1.05, 0.0, 0.0)};
  // anchors at nodes 4 and 13: 0.65 mm back, 0.25 mm ahead → the nearer
  const auto both = cutEndLength(chain, alive, cut, {4, 13});
  ASSERT_TRUE(both.has_value());
  EXPECT_NEAR(*both, 0.25, 1e-9);
  const auto back = cutEndLength(chain, alive, cut, {4});
  ASSERT_TRUE(back.has_value());
  EXPECT_NEAR(*back, 0.65, 1e-9);
  // an anchor beyond a broken link is not reached
  alive[6] = 0;
  EXPECT_FALSE(cutEndLength(chain, alive, cut, {4}).has_value());
  EXPECT_FALSE(cutEndLength(chain, alive, cut, {}).has_value());
}

TEST(Microscissors, TheNeedleKeepsItsPieceFromTheSwageToTheCut) {
  const Points chain = straightChain(30, 0.0, 0.0);
  std::vector<std::uint8_t> alive(30, 1);
  EXPECT_NEAR(threadOnNeedle(chain, alive, 5), 2.5, 1e-9);
  EXPECT_TRUE(onNeedlePiece(alive, 5, 12));
  EXPECT_FALSE(onNeedlePiece(alive, 5, 3));  // the needle's own links
  alive[8] = 0;
  EXPECT_NEAR(threadOnNeedle(chain, alive, 5), 0.3, 1e-9);
  EXPECT_FALSE(onNeedlePiece(alive, 5, 12));  // a snippet already cut off
  EXPECT_TRUE(onNeedlePiece(alive, 5, 7));
}

}  // namespace
}  // namespace microsim::sim::tools
