// The solvers that take soft point terms (SpringControls::springs): newton and reference
// against closed forms, against each other, and on bad input.
#include "microsim/sim/mesh/lattice.h"
#include "microsim/sim/solve/solver.h"
#include "microsim/sim/solve/spring_kernels.h"
#include "solve_test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace microsim::sim {
namespace {

using testing::maxDistance;

class PointSpringSolver : public ::testing::TestWithParam<std::string> {};

/// A node on a link to a fixed node at the origin, pulled by a two-sided term to `anchor`.
struct PointSpringTether {
  SpringModel model;
  SpringControls controls;
};

PointSpringTether pointSpringTether(double linkK, double rest, double springK, const Vec3& anchor) {
  PointSpringTether t;
  t.model.addNode(Vec3::Zero());
  t.model.addNode(Vec3(rest, 0, 0));
  t.model.addLink(0, 1, linkK);
  t.model.setFixed(0);
  t.model.finalize();
  PointSpring s;
  s.nodes[0] = 1;
  s.weights[0] = 1.0;
  s.anchor = anchor;
  s.k = springK;
  t.controls.springs.push_back(s);
  return t;
}

TEST_P(PointSpringSolver, ZeroRestLinkAndTermMeetHalfway) {
  // zero-rest link k to the origin and zero-rest term k to A: the node sits at A / 2
  SpringModel model;
  model.addNode(Vec3::Zero());
  model.addNode(Vec3(0.5, 0.5, 0.5));
  model.addLink(0, 1, 10.0, 0.0);
  model.setFixed(0);
  model.finalize();
  SpringControls controls;
  PointSpring s;
  s.nodes[0] = 1;
  s.weights[0] = 1.0;
  s.anchor = Vec3(2.0, -4.0, 6.0);
  s.k = 10.0;
  controls.springs.push_back(s);
  SpringState state = SpringState::atRest(model);
  auto solver = makeSolver(GetParam());
  SolveBudget budget;
  budget.maxIterations = 50;
  budget.residualTolerance = 1e-10;
  const SolveReport r = solver->solve(model, state, controls, budget);
  EXPECT_EQ(r.status, SolveStatus::Converged);
  EXPECT_LT((state.x.col(1) - Vec3(1.0, -2.0, 3.0)).norm(), 1e-9);
  EXPECT_TRUE(state.x.col(0).isZero(0.0));
}

TEST_P(PointSpringSolver, TetheredNodeSitsWhereLinkAndTermBalance) {
  // link k1 with rest r from the origin, term k2 to A: the node lies on the ray to A at s
  // with k1 (s − r) = k2 (|A| − s), s = (k1 r + k2 |A|) / (k1 + k2)
  const Vec3 anchor(3.0, 4.0, 0.0);
  for (const auto& [k1, k2] : {std::pair{10.0, 10.0}, std::pair{10.0, 30.0}}) {
    SCOPED_TRACE(k2);
    const PointSpringTether t = pointSpringTether(k1, 1.0, k2, anchor);
    SpringState state = SpringState::atRest(t.model);
    auto solver = makeSolver(GetParam());
    SolveBudget budget;
    budget.maxIterations = 50;
    budget.residualTolerance = 1e-10;
    const SolveReport r = solver->solve(t.model, state, t.controls, budget);
    EXPECT_EQ(r.status, SolveStatus::Converged);
    EXPECT_LE(r.residual, 1e-10);
    const double s = (k1 * 1.0 + k2 * 5.0) / (k1 + k2);
    EXPECT_LT((state.x.col(1) - s * anchor / 5.0).norm(), 1e-8);
    EXPECT_NEAR(relativeResidual(t.model, state.x, t.controls), r.residual, 1e-12);
  }
}

/// A 4³ box, bottom fixed, and a rigid plate at z = plate pressing down on every free
/// node with a one-sided term of stiffness k (normal −z, gap 0).
struct PointSpringPress {
  SpringModel model = latticeBox(4, 10.0);
  SpringControls controls;
};

PointSpringPress pointSpringPress(double plate, double k) {
  PointSpringPress p;
  const auto rest = p.model.restPositions();
  for (int i = 0; i < p.model.nodeCount(); ++i) {
    if (p.model.isFixed(i)) continue;
    PointSpring s;
    s.nodes[0] = i;
    s.weights[0] = 1.0;
    s.anchor = Vec3(rest(0, i), rest(1, i), plate);
    s.normal = -Vec3::UnitZ();
    s.k = k;
    p.controls.springs.push_back(s);
  }
  return p;
}

TEST_P(PointSpringSolver, PlatePressingABoxHoldsItsTopBelowThePlate) {
  const double plate = 2.5;  // the top face is at z = 3
  const double k = 1000.0;
  const PointSpringPress p = pointSpringPress(plate, k);
  SpringState state = SpringState::atRest(p.model);
  auto solver = makeSolver(GetParam());
  SolveBudget budget;
  budget.maxIterations = 100;
  budget.residualTolerance = 1e-9;
  const SolveReport r = solver->solve(p.model, state, p.controls, budget);
  EXPECT_EQ(r.status, SolveStatus::Converged);
  EXPECT_LE(relativeResidual(p.model, state.x, p.controls), budget.residualTolerance);

  // each node above the plate carries the links' push: it is past the plate by that force
  // over k, and the links' force on it points up into the plate
  Points linkForces;
  totalForces(p.model, state.x, linkForces);
  int pressed = 0;
  double deepest = 0.0;
  for (int i = 0; i < p.model.nodeCount(); ++i) {
    const double past = state.x(2, i) - plate;
    if (past <= 0.0) continue;
    ++pressed;
    deepest = std::max(deepest, past);
    EXPECT_LE(past, linkForces.col(i).norm() / k + 1e-9) << "node " << i;
    EXPECT_GT(linkForces(2, i), 0.0) << "node " << i;
  }
  // the whole top face is pressed, by less than 1% of the plate's travel
  EXPECT_EQ(pressed, 16);
  EXPECT_LT(deepest, 0.005);
  EXPECT_GT(deepest, 0.0);
}

TEST_P(PointSpringSolver, PlatePressMatchesTheReference) {
  const PointSpringPress p = pointSpringPress(2.2, 500.0);
  const SpringState start = SpringState::atRest(p.model);
  const SpringState reference = testing::referenceOf(p.model, start, p.controls);
  SpringState state = start;
  auto solver = makeSolver(GetParam());
  SolveBudget budget;
  budget.maxIterations = 100;
  budget.residualTolerance = 1e-10;
  EXPECT_EQ(solver->solve(p.model, state, p.controls, budget).status, SolveStatus::Converged);
  EXPECT_LT(maxDistance(state.x, reference.x), 1e-6);
  // the plate did something: the top face went down the 0.8 mm to within 0.02 mm of it
  EXPECT_LT(state.x(2, latticeTopMiddle(4)), 2.22);
}

TEST_P(PointSpringSolver, TermsWithBadNodesOrValuesAreRejectedUntouched) {
  const PointSpringTether good = pointSpringTether(10.0, 1.0, 10.0, Vec3(3, 4, 0));
  PointSpring base = good.controls.springs[0];
  std::vector<PointSpring> bad;
  {
    PointSpring s = base;
    s.nodes[0] = 2;  // past the last node
    bad.push_back(s);
  }
  {
    PointSpring s = base;
    s.nodes[0] = -3;  // no node at all
    bad.push_back(s);
  }
  {
    PointSpring s = base;
    s.nodes = {1, 5, -1, -1};
    s.weights = {1.0, -1.0, 0.0, 0.0};
    bad.push_back(s);
  }
  {
    PointSpring s = base;
    s.anchor.y() = std::numeric_limits<double>::quiet_NaN();
    bad.push_back(s);
  }
  {
    PointSpring s = base;
    s.normal = Vec3(0, 0, std::numeric_limits<double>::infinity());
    bad.push_back(s);
  }
  {
    PointSpring s = base;
    s.k = std::numeric_limits<double>::quiet_NaN();
    bad.push_back(s);
  }
  {
    PointSpring s = base;
    s.weights[0] = std::numeric_limits<double>::quiet_NaN();
    bad.push_back(s);
  }
  for (std::size_t b = 0; b < bad.size(); ++b) {
    SCOPED_TRACE(b);
    SpringControls controls = good.controls;
    controls.springs.push_back(bad[b]);
    SpringState state = SpringState::atRest(good.model);
    state.x.col(1) = Vec3(0.9, 0.1, -0.2);
    state.v.col(1) = Vec3(1.0, 2.0, 3.0);
    const SpringState before = state;
    auto solver = makeSolver(GetParam());
    const SolveReport r = solver->solve(good.model, state, controls, {});
    EXPECT_EQ(r.status, SolveStatus::InvalidInput);
    EXPECT_TRUE(state.x == before.x);  // untouched: every value as it was
    EXPECT_TRUE(state.v == before.v);
  }
}

INSTANTIATE_TEST_SUITE_P(Solvers, PointSpringSolver, ::testing::Values("newton", "reference"),
                         [](const auto& info) { return info.param; });

TEST(PointSpringSolverSupport, NewtonAndReferenceTakeTermsAndQssDoesNot) {
  EXPECT_TRUE(makeSolver("newton")->supportsPointSprings());
  EXPECT_TRUE(makeSolver("reference")->supportsPointSprings());
  EXPECT_FALSE(makeSolver("qss")->supportsPointSprings());
}

TEST(PointSpringSolverSupport, ResidualCountsTheTerms) {
  // the tethered node at rest: the link is slack, only the term pulls (k |A − x| = 10·√20)
  const PointSpringTether t = pointSpringTether(10.0, 1.0, 10.0, Vec3(3, 4, 0));
  const SpringState state = SpringState::atRest(t.model);
  const double scale = forceScale(t.model, t.controls);
  EXPECT_NEAR(relativeResidual(t.model, state.x, t.controls) * scale, 10.0 * std::sqrt(20.0), 1e-9);
  EXPECT_EQ(relativeResidual(t.model, state.x, {}), 0.0);
}

}  // namespace
}  // namespace microsim::sim
