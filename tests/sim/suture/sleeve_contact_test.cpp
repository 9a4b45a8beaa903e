// Turns wound on a forceps' jaws kept in a shell round them (suture_contact.h, Sleeve): the
// jaws of the shipped forceps (3 mm long; capsules 0.12 mm round over the tip half, 0.19 over
// the heel half; the slab between opened jaws 0.12 thick each side of their plane) standing
// along +z from tips at the origin, with a thread of radius 0.01 and 0.03 mm of slack.
#include "microsim/sim/suture/suture_contact.h"

#include "support/chain_points.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace microsim::sim::suture {
namespace {

using microsim::testing::chainOf;

constexpr double kThread = 0.01;
constexpr double kTipHalf = 0.12;
constexpr double kHeelHalf = 0.19;
constexpr double kSlack = 0.03;

/// The jaws opened so that their tips stand `spread` mm either side of the z axis (along x);
/// nodes `first`..`last` wound on them.
Sleeve jaws(double spread, int first, int last) {
  Sleeve s;
  s.hinge = Vec3(0.0, 0.0, 3.0);
  s.tipA = Vec3(spread, 0.0, 0.0);
  s.tipB = Vec3(-spread, 0.0, 0.0);
  for (std::size_t j = 0; j < 2; ++j) {
    const Vec3 tip = j == 0 ? s.tipA : s.tipB;
    const Vec3 middle = 0.5 * (tip + s.hinge);
    s.jaws[2 * j] = {tip, middle, kTipHalf};
    s.jaws[2 * j + 1] = {middle, s.hinge, kHeelHalf};
  }
  s.slabRadius = kTipHalf;
  s.slack = kSlack;
  s.first = first;
  s.last = last;
  return s;
}

int project(Points& x, const Sleeve& sleeve, std::vector<std::uint8_t>& touched) {
  const Points start = x;
  const std::vector<std::uint8_t> movable(static_cast<std::size_t>(x.cols()), 1);
  touched.assign(static_cast<std::size_t>(x.cols()), 0);
  return projectSleeves(x, start, std::vector<Sleeve>{sleeve}, kThread, 0.0, movable, touched);
}

TEST(SleeveContact, AWoundNodeIsKeptBetweenTheJawsSurfaceAndTheSlackBeyondIt) {
  // closed jaws; 1 mm up (the tip half): one node pressed in, one loose, one in the shell,
  // one far off but not wound
  Points x = chainOf(
      {Vec3(0.05, 0.0, 1.0), Vec3(0.0, 0.5, 1.0), Vec3(-0.145, 0.0, 1.0), Vec3(2.0, 0.0, 1.0)});
  std::vector<std::uint8_t> touched;
  EXPECT_EQ(project(x, jaws(0.0, 0, 2), touched), 2);
  EXPECT_NEAR(std::hypot(x(0, 0), x(1, 0)), kTipHalf + kThread, 1e-12);
  EXPECT_NEAR(std::hypot(x(0, 1), x(1, 1)), kTipHalf + kThread + kSlack, 1e-12);
  EXPECT_DOUBLE_EQ(x(0, 2), -0.145);
  EXPECT_DOUBLE_EQ(x(0, 3), 2.0);
  // pushed and pulled along the way out of the jaws, at their height
  EXPECT_GT(x(0, 0), 0.0);
  EXPECT_GT(x(1, 1), 0.0);
  EXPECT_DOUBLE_EQ(x(2, 0), 1.0);
  EXPECT_DOUBLE_EQ(x(2, 1), 1.0);
  EXPECT_EQ(touched, (std::vector<std::uint8_t>{1, 1, 0, 0}));
}

TEST(SleeveContact, OverTheHeelHalfTheShellIsTheThickerCapsules) {
  Points x = chainOf({Vec3(0.0, 0.15, 2.5)});
  std::vector<std::uint8_t> touched;
  EXPECT_EQ(project(x, jaws(0.0, 0, 0), touched), 1);
  EXPECT_NEAR(x.col(0).head<2>().norm(), kHeelHalf + kThread, 1e-12);
}

TEST(SleeveContact, ATurnRoundOpenedJawsLiesRoundBothNotBetweenThem) {
  // tips 0.5 mm apart; 1 mm up the jaws' axes stand 0.33 mm apart: a node between them, just
  // off their plane on either side, goes out of the slab on its own side; one pressed into a
  // jaw from outside goes out of that jaw's capsule
  const Sleeve open = jaws(0.25, 0, 2);
  Points x = chainOf({Vec3(0.0, 0.02, 1.0), Vec3(0.0, -0.02, 1.0), Vec3(0.18, 0.0, 1.0)});
  std::vector<std::uint8_t> touched;
  EXPECT_EQ(project(x, open, touched), 3);
  EXPECT_NEAR(x(1, 0), kTipHalf + kThread, 1e-12);
  EXPECT_NEAR(x(1, 1), -(kTipHalf + kThread), 1e-12);
  EXPECT_GT(x(0, 2), 0.18);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(hullOffset(open, x.col(i), x.col(i)).distance, kThread, 1e-12) << i;
}

TEST(SleeveContact, ANodeOnThePlaneBetweenTheJawsGoesBackToTheSideItCameFrom) {
  const Sleeve open = jaws(0.25, 0, 0);
  const Vec3 between(0.0, 0.0, 1.0);
  EXPECT_NEAR(hullOffset(open, between, Vec3(0.0, -1.0, 1.0)).normal.y(), -1.0, 1e-12);
  EXPECT_NEAR(hullOffset(open, between, Vec3(0.0, 1.0, 1.0)).normal.y(), 1.0, 1e-12);
  EXPECT_NEAR(hullOffset(open, between, between).distance, -kTipHalf, 1e-12);
}

}  // namespace
}  // namespace microsim::sim::suture
