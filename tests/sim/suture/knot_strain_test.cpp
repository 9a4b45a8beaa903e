// The knot-break rule on hand-placed threads: a link stretched past knotBreakStretch, with a
// strand pressed against it from the side and something pulling it from both ends, breaks
// once held so for kKnotBreakSeconds; a shorter hold, a strand lying along it, or a piece with
// a free end does not.
#include "microsim/sim/suture/knot_strain.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <vector>

namespace microsim::sim::suture {
namespace {

constexpr int kSkip = 3;

// 40 links of 0.1 mm along +x; link 20 stretched to `stretch` (the nodes after it moved on)
// and, when `across`, the last ten nodes bent back to run over it along -y 0.02 mm above
// (one diameter: a strand pressed on it from the side); otherwise they fold back along x.
struct Thread {
  SutureModel model;
  SutureState state;
  std::vector<std::uint8_t> pressed;
};

Thread threadWithACrossing(double stretch, bool across) {
  SutureDef d;
  d.links = 40;
  d.needleLinks = 0;
  d.length = 4.0;
  Thread t{SutureModel(d), {}, {}};
  t.state = SutureState::laidOut(t.model);
  double at = 0.0;
  for (int i = 0; i <= 30; ++i) {
    t.state.x.col(i) = Vec3(at, 0.0, 0.0);
    at += i == 20 ? 0.1 * (1.0 + stretch) : 0.1;
  }
  const Vec3 over =
      0.5 * (t.state.x.col(20) + t.state.x.col(21)) + Vec3(0.0, 0.0, 2.0 * d.contactRadius);
  for (int i = 31; i <= 40; ++i) {
    const double s = 0.1 * (i - 35);
    t.state.x.col(i) = across ? Vec3(over + Vec3(0.0, -s, 0.0))
                              : Vec3(over + Vec3(-s, 0.0, -2.0 * d.contactRadius));
  }
  t.state.xPrev = t.state.x;
  t.pressed.assign(41, 0);
  t.pressed[20] = t.pressed[21] = 1;
  return t;
}

const std::vector<Grip> kBothEnds = {{0, Vec3::Zero()}, {40, Vec3::Zero()}};

TEST(KnotStrain, ALinkPressedFromTheSideAndHeldPastTheLimitBreaksOnceHeldLongEnough) {
  Thread t = threadWithACrossing(0.15, true);
  const double h = 0.0025;
  int steps = 0;
  std::optional<int> broke;
  while (!broke && steps < 100) {
    broke = findKnotBreak(t.model, t.state, kBothEnds, t.pressed, kSkip, h);
    ++steps;
  }
  ASSERT_TRUE(broke.has_value());
  EXPECT_EQ(*broke, 20);
  // 0.03 s of 2.5 ms substeps: the twelfth (floating-point sums may take a thirteenth)
  EXPECT_GE(steps, 12);
  EXPECT_LE(steps, 13);
  // every hold starts again after a break
  for (double held : t.state.heldPastBreak) EXPECT_EQ(held, 0.0);
}

TEST(KnotStrain, ABelowTheLimitOrInterruptedHoldDoesNotBreak) {
  Thread under = threadWithACrossing(0.08, true);
  for (int k = 0; k < 40; ++k)
    EXPECT_FALSE(findKnotBreak(under.model, under.state, kBothEnds, under.pressed, kSkip, 0.0025));

  // held past the limit for 0.02 s, released for a substep, held 0.02 s again
  Thread t = threadWithACrossing(0.15, true);
  const std::vector<std::uint8_t> none(41, 0);
  for (int round = 0; round < 3; ++round) {
    for (int k = 0; k < 8; ++k)
      EXPECT_FALSE(findKnotBreak(t.model, t.state, kBothEnds, t.pressed, kSkip, 0.0025));
    EXPECT_FALSE(findKnotBreak(t.model, t.state, kBothEnds, none, kSkip, 0.0025));
  }
}

TEST(KnotStrain, AStrandAlongTheLinkOrAFreeEndCarriesNoKnot) {
  // folded back along its own line: the contact there pushes along the thread
  Thread along = threadWithACrossing(0.15, false);
  for (int k = 0; k < 40; ++k)
    EXPECT_FALSE(findKnotBreak(along.model, along.state, kBothEnds, along.pressed, kSkip, 0.0025));

  // held at one end only: nothing pulls the crossing from the other side
  Thread free = threadWithACrossing(0.15, true);
  const std::vector<Grip> oneEnd = {{0, Vec3::Zero()}};
  for (int k = 0; k < 40; ++k)
    EXPECT_FALSE(findKnotBreak(free.model, free.state, oneEnd, free.pressed, kSkip, 0.0025));
}

TEST(KnotStrain, AGripOnOneSideAndAPierceOnTheOtherPullTheKnot) {
  // a knot tied over a stitch: the hand holds one end, the tissue the thread through it
  Thread t = threadWithACrossing(0.15, true);
  Pierce hole;
  hole.face = 0;
  hole.barycentric = Vec3(1, 0, 0);
  hole.node = 38;
  hole.point = t.state.x.col(38);
  t.state.pierces.push_back(hole);
  const std::vector<Grip> hand = {{0, Vec3::Zero()}};
  std::optional<int> broke;
  for (int k = 0; k < 20 && !broke; ++k)
    broke = findKnotBreak(t.model, t.state, hand, t.pressed, kSkip, 0.0025);
  ASSERT_TRUE(broke.has_value());
  EXPECT_EQ(*broke, 20);

  // a hole before the crossing (node 15): links 15-40 have nothing pulling beyond them
  Thread beyond = threadWithACrossing(0.15, true);
  hole.node = 15;
  beyond.state.pierces.push_back(hole);
  for (int k = 0; k < 40; ++k)
    EXPECT_FALSE(findKnotBreak(beyond.model, beyond.state, hand, beyond.pressed, kSkip, 0.0025));
}

}  // namespace
}  // namespace microsim::sim::suture
