// DESIGN.md's hard cases for tissue, each solver's outcome asserted: it converges, or it
// stops and says why; never NaN, never an energy or residual blow-up.
#include "microsim/sim/solve/solver.h"
#include "microsim/sim/solve/spring_kernels.h"
#include "microsim/sim/solve/state_hash.h"
#include "solve_test_util.h"

#include <gtest/gtest.h>

#include <limits>

namespace microsim::sim {
namespace {

using testing::paramsFor;
using testing::topPull;

bool isQuasiStatic(const std::string& name) { return name != "rk4" && name != "implicit"; }

class HardCase : public ::testing::TestWithParam<std::string> {
 protected:
  /// Solves with `iterations`, checks the invariants, returns the report.
  SolveReport run(const SpringModel& model, SpringState& state, const SpringControls& controls,
                  int iterations, double tolerance = 0.0) {
    const double before = relativeResidual(model, state.x, controls);
    auto solver = makeSolver(GetParam(), paramsFor(GetParam()));
    SolveBudget budget;
    budget.maxIterations = iterations;
    budget.residualTolerance = tolerance;
    const SolveReport r = solver->solve(model, state, controls, budget);
    EXPECT_TRUE(state.x.allFinite());
    EXPECT_TRUE(state.v.allFinite());
    EXPECT_TRUE(std::isfinite(r.residual));
    EXPECT_NE(r.status, SolveStatus::InvalidInput);
    EXPECT_NE(r.status, SolveStatus::Diverged);
    // the residual after imposing the controls bounds what a sane solve may end with
    SpringState imposed = state;
    for (int c = 0; c < controls.size(); ++c) imposed.x.col(controls.nodes[c]) = controls.targets.col(c);
    EXPECT_LE(relativeResidual(model, state.x, controls), std::max(before, 1.0) * 10.0);
    return r;
  }
};

TEST_P(HardCase, StiffnessRatio1000To1) {
  const int n = 4;
  SpringModel soft = latticeBox(n, 1.0);
  SpringModel model;
  for (int i = 0; i < soft.nodeCount(); ++i) model.addNode(soft.restPositions().col(i));
  for (const Link& l : soft.links()) {
    const bool lower = soft.restPositions()(2, l.a) < 1.5 && soft.restPositions()(2, l.b) < 1.5;
    model.addLink(l.a, l.b, lower ? 1000.0 : 1.0);
  }
  for (int i : soft.fixedNodes()) model.setFixed(i);
  model.finalize();
  SpringState state = SpringState::atRest(model);
  const SolveReport r = run(model, state, topPull(n, 1.0), isQuasiStatic(GetParam()) ? 400 : 600, 1e-8);
  if (GetParam() == "newton" || GetParam() == "reference") {
    EXPECT_EQ(r.status, SolveStatus::Converged);
  }
  EXPECT_LT(r.residual, 0.05);
}

TEST_P(HardCase, ControlDisplacementOfTenRestLengths) {
  const int n = 3;
  const SpringModel model = latticeBox(n, 10.0);
  SpringState state = SpringState::atRest(model);
  const SolveReport r = run(model, state, topPull(n, 10.0), 400, 1e-8);
  if (GetParam() == "newton" || GetParam() == "reference") {
    EXPECT_EQ(r.status, SolveStatus::Converged);
  }
  EXPECT_LT(r.residual, 0.05);
  // the pulled node's neighbours followed it upward
  EXPECT_GT(state.x.row(2).maxCoeff(), 5.0);
}

TEST_P(HardCase, ZeroAndNearZeroLengthSprings) {
  SpringModel model;
  model.addNode(Vec3(0, 0, 0));
  model.addNode(Vec3(1, 0, 0));
  model.addNode(Vec3(1, 0, 0));         // coincides with node 1
  model.addNode(Vec3(1 + 1e-10, 0, 0));  // almost coincides
  model.addNode(Vec3(2, 0, 0));
  model.addLink(0, 1, 10.0);
  model.addLink(1, 2, 10.0, 0.0);                                   // zero-length
  model.addLink(2, 3, 10.0);                                        // near-zero rest
  model.addLink(1, 3, 10.0, 0.0, StiffnessLaw::Stiffening, 50.0);   // zero rest: no stiffening
  model.addLink(3, 4, 10.0);
  model.addLink(0, 2, 5.0);
  model.setFixed(0);
  model.finalize();
  SpringControls controls;
  controls.add(4, Vec3(2.5, 0.5, 0));
  SpringState state = SpringState::atRest(model);
  const SolveReport r = run(model, state, controls, isQuasiStatic(GetParam()) ? 2000 : 3000, 1e-8);
  if (GetParam() == "newton" || GetParam() == "reference") {
    EXPECT_EQ(r.status, SolveStatus::Converged);
  }
  EXPECT_LT(r.residual, 1e-3);
}

TEST_P(HardCase, CoincidentNodes) {
  // two linked nodes (rest 1) that start on top of each other, each tied to a fixed anchor
  SpringModel model;
  model.addNode(Vec3(0, 0, 0));
  model.addNode(Vec3(1, 0.2, 0));
  model.addNode(Vec3(1, 0.2, 0));
  model.addNode(Vec3(2, 0, 0));
  model.addLink(0, 1, 10.0);
  model.addLink(1, 2, 10.0, 1.0);
  model.addLink(2, 3, 10.0);
  model.setFixed(0);
  model.setFixed(3);
  model.finalize();
  SpringState state = SpringState::atRest(model);
  const SolveReport r = run(model, state, {}, 500, 1e-8);
  EXPECT_LT(r.residual, 10.0);
}

TEST_P(HardCase, CuttingLinksMidSolve) {
  const int n = 4;
  SpringModel model = latticeBox(n, 10.0);
  const SpringControls controls = topPull(n, 1.0);
  SpringState state = SpringState::atRest(model);
  auto solver = makeSolver(GetParam(), paramsFor(GetParam()));
  SolveBudget budget;
  budget.maxIterations = 5;
  solver->solve(model, state, controls, budget);
  // cut every link of one free node, and a band of links around the pulled node
  const int victim = latticeIndex(n, 1, 1, 2);
  for (int li : model.linksOf(victim)) model.removeLink(li);
  for (int li : model.linksOf(controls.nodes[0]))
    if (li % 2 == 0) model.removeLink(li);
  budget.maxIterations = isQuasiStatic(GetParam()) ? 300 : 600;
  budget.residualTolerance = 1e-8;
  const SolveReport r = solver->solve(model, state, controls, budget);
  EXPECT_TRUE(state.x.allFinite());
  EXPECT_NE(r.status, SolveStatus::Diverged);
  EXPECT_LT(r.residual, 0.05);
  if (GetParam() == "newton" || GetParam() == "reference") {
    EXPECT_EQ(r.status, SolveStatus::Converged);
    EXPECT_LE(relativeResidual(model, state.x, controls), 1e-8);
  }
}

TEST_P(HardCase, TimeBudgetFarTooShort) {
  const int n = 6;
  const SpringModel model = latticeBox(n, 10.0);
  SpringState state = SpringState::atRest(model);
  auto solver = makeSolver(GetParam(), paramsFor(GetParam()));
  SolveBudget budget;
  budget.maxSeconds = 1e-12;
  const SolveReport r = solver->solve(model, state, topPull(n, 1.0), budget);
  if (GetParam() != "reference") {
    EXPECT_EQ(r.status, SolveStatus::TimeLimit);
  }
  EXPECT_LE(r.iterations, 1);
  EXPECT_TRUE(state.x.allFinite());
  // the control node is where the tool put it
  EXPECT_EQ(state.x.col(latticeTopMiddle(n)), topPull(n, 1.0).targets.col(0));
}

TEST_P(HardCase, InvalidInputLeavesTheStateUntouched) {
  const SpringModel model = latticeBox(3, 10.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto solver = makeSolver(GetParam(), paramsFor(GetParam()));
  SolveBudget budget;
  budget.maxIterations = 3;

  SpringState state = SpringState::atRest(model);
  state.x(1, 4) = nan;
  std::uint64_t before = stateHash(state);
  EXPECT_EQ(solver->solve(model, state, topPull(3, 1.0), budget).status, SolveStatus::InvalidInput);
  EXPECT_EQ(stateHash(state), before);

  state = SpringState::atRest(model);
  state.v(0, 7) = std::numeric_limits<double>::infinity();
  before = stateHash(state);
  EXPECT_EQ(solver->solve(model, state, topPull(3, 1.0), budget).status, SolveStatus::InvalidInput);
  EXPECT_EQ(stateHash(state), before);

  state = SpringState::atRest(model);
  before = stateHash(state);
  SpringControls bad = topPull(3, 1.0);
  bad.targets(2, 0) = nan;
  EXPECT_EQ(solver->solve(model, state, bad, budget).status, SolveStatus::InvalidInput);
  SpringControls outOfRange;
  outOfRange.add(model.nodeCount(), Vec3::Zero());
  EXPECT_EQ(solver->solve(model, state, outOfRange, budget).status, SolveStatus::InvalidInput);
  EXPECT_EQ(stateHash(state), before);
}

INSTANTIATE_TEST_SUITE_P(Solvers, HardCase,
                         ::testing::Values("qss", "rk4", "implicit", "newton", "reference"));

TEST(HardCaseQss, DivergenceRestoresTheState) {
  // a hand-set α far above the stable step blows up; the input comes back intact
  const SpringModel model = latticeBox(4, 10.0);
  SolverParams wild;
  wild.alpha = 5.0;
  SpringState state = SpringState::atRest(model);
  const std::uint64_t before = stateHash(state);
  SolveBudget budget;
  budget.maxIterations = 500;
  const SolveReport r = makeSolver("qss", wild)->solve(model, state, topPull(4, 1.0), budget);
  EXPECT_EQ(r.status, SolveStatus::Diverged);
  EXPECT_EQ(stateHash(state), before);
}

TEST(HardCaseRk4, StiffMeshStaysStableBySubstepping) {
  // k = 10⁴ with m = 1 and a 1/30 s cycle is 15 times the explicit stability limit:
  // rk4 substeps below it and stays finite
  const SpringModel model = latticeBox(3, 1e4);
  SpringState state = SpringState::atRest(model);
  SolveBudget budget;
  budget.maxIterations = 3;
  const SolveReport r = makeSolver("rk4")->solve(model, state, topPull(3, 1.0), budget);
  EXPECT_EQ(r.status, SolveStatus::IterationLimit);
  EXPECT_TRUE(state.x.allFinite());
}

}  // namespace
}  // namespace microsim::sim
