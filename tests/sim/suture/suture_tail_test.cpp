#include "microsim/sim/suture/bending_limit.h"
#include "microsim/sim/suture/suture_solver.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace microsim::sim::suture {
namespace {

// a 200-link thread (0.1 mm links) laid along x, held at node 0 by a hand moving on a 2 mm
// circle at one cycle per second (≈ 0.13 mm per 10 ms frame), the rest free
struct DraggedTail {
  SutureModel model;
  SutureState state;
  Vec3 start = Vec3::Zero();

  explicit DraggedTail(double gravity) : model(def()) {
    model.gravity = Vec3(0.0, 0.0, -gravity);
    state = SutureState::laidOut(model);
    start = state.x.col(0);
  }
  static SutureDef def() {
    SutureDef d;
    d.links = 200;
    d.needleLinks = 0;
    d.length = 20.0;
    return d;
  }
  Grip grip(int frame) const {
    const double phase = 2.0 * std::numbers::pi * frame * 0.01;
    return {0, start + 2.0 * Vec3(std::sin(phase), std::cos(phase) - 1.0, 0.3 * std::sin(2.0 * phase))};
  }
};

// follow-the-leader outward as the direct solver's predictor whipped a dragged free tail into
// an explosion (nodes moving tens of mm per step after ten frames)
TEST(SutureTail, DirectSolverKeepsADraggedFreeTailBounded) {
  DraggedTail t(0.0);
  auto solver = makeSutureSolver("direct");
  double fastest = 0.0;
  for (int k = 1; k <= 60; ++k) {
    const Points before = t.state.x;
    const Grip g = t.grip(k);
    const SutureStepReport r = solver->step(t.model, t.state, std::span<const Grip>(&g, 1), {});
    ASSERT_EQ(r.status, SutureStepStatus::Ok);
    fastest = std::max(fastest, std::sqrt((t.state.x - before).colwise().squaredNorm().maxCoeff()));
    EXPECT_LT(r.maxStretch, 1e-6);
  }
  // the hand moves at most ≈ 0.13 mm per frame; the tail may not outrun it by much
  EXPECT_LT(fastest, 0.5);
}

// A thread of 0.15 mm links (the shipped scenes') through one hole (node 40), its free tail
// lying nearly at right angles to it, drawn through from the other end 0.03 mm a frame for
// 1.8 mm (the hole slides on a node every five frames). The tail follows as thread does: it
// stays straight, and its end moves at most about a link and a half in a frame. Before a slid
// hole re-laid the free tail (suture_solver.cpp), the substep after each slide carried the
// tail a link and kept that as speed: the end whipped on by up to 0.9 mm a frame and the tail
// piled up at the hole (its end 0.42 of the tail's length from it).
TEST(SutureTail, AFreeTailDrawnThroughAHoleFollowsWithoutWhipping) {
  SutureDef d;
  d.links = 100;
  d.needleLinks = 0;
  d.length = 15.0;
  const SutureModel model(d);
  SutureState state = SutureState::laidOut(model);
  constexpr double kLink = 0.15;
  for (int i = 0; i <= 100; ++i)
    state.x.col(i) = i <= 40 ? Vec3(kLink * i, 0.0, 0.0)
                             : Vec3(40 * kLink + 0.02 * (i - 40), kLink * (i - 40), 0.0);
  state.xPrev = state.x;
  Pierce hole;
  hole.face = 0;
  hole.barycentric = Vec3(1.0, 0.0, 0.0);
  hole.node = 40;
  hole.point = state.x.col(40);
  state.pierces.push_back(hole);
  auto solver = makeSutureSolver("direct");
  double fastestEnd = 0.0;
  for (int k = 1; k <= 60; ++k) {
    const Vec3 end = state.x.col(100);
    const Grip g{0, Vec3(-0.03 * k, 0.0, 0.0)};
    ASSERT_EQ(solver->step(model, state, std::span<const Grip>(&g, 1), {}).status,
              SutureStepStatus::Ok);
    fastestEnd = std::max(fastestEnd, (state.x.col(100) - end).norm());
  }
  ASSERT_EQ(state.pierces.size(), 1u);
  EXPECT_GE(state.pierces[0].node, 50);  // 1.8 mm drawn through: 12 links
  EXPECT_LE(fastestEnd, 0.3);
  const int at = state.pierces[0].node;
  EXPECT_GE((state.x.col(100) - state.x.col(at)).norm() / model.arc(at, 100), 0.95)
      << "the tail piled up at the hole";
}

TEST(SutureTail, HangingTailHasNoTurnSharperThanTheLimit) {
  for (const std::string& name : sutureSolverNames()) {
    DraggedTail t(9810.0);
    auto solver = makeSutureSolver(name);
    for (int k = 1; k <= 60; ++k) {
      const Grip g = t.grip(k);
      ASSERT_EQ(solver->step(t.model, t.state, std::span<const Grip>(&g, 1), {}).status,
                SutureStepStatus::Ok);
    }
    EXPECT_LE(maxTurnAngle(t.state.x, t.state.alive, 0, t.model.nodeCount() - 1),
              kDefaultMaxTurn + 0.05)
        << name;
  }
}

TEST(SutureTail, BendingLimitOpensAHairpinAndLeavesGentleTurns) {
  Points x(3, 4);
  x.col(0) = Vec3(0.0, 0.0, 0.0);
  x.col(1) = Vec3(1.0, 0.0, 0.0);
  x.col(2) = Vec3(0.2, 0.1, 0.0);  // a hairpin at node 1
  x.col(3) = Vec3(-0.5, 0.8, 0.0);  // a gentle turn at node 2
  const std::vector<double> rest = {1.0, 1.0, 1.0};
  const std::vector<std::uint8_t> alive = {1, 1, 1};
  const std::vector<std::uint8_t> free = {1, 1, 1, 1};
  const Points gentle = x;
  const int corrected = limitBending(x, rest, alive, free, kDefaultMaxTurn);
  EXPECT_EQ(corrected, 1);
  // 120° at unit links: the outer nodes at least one link length apart
  EXPECT_NEAR((x.col(2) - x.col(0)).norm(), 1.0, 1e-12);
  EXPECT_TRUE(x.col(1).isApprox(gentle.col(1)));

  // a held node is never moved
  Points y = gentle;
  const std::vector<std::uint8_t> held = {0, 1, 1, 1};
  EXPECT_EQ(limitBending(y, rest, alive, held, kDefaultMaxTurn), 0);
  EXPECT_TRUE(y.isApprox(gentle));
}

}  // namespace
}  // namespace microsim::sim::suture
