// Every solver against closed forms and against the reference equilibrium.
#include "microsim/sim/solve/solver.h"
#include "microsim/sim/solve/state_hash.h"
#include "microsim/sim/solve/spring_kernels.h"
#include "solve_test_util.h"

#include <gtest/gtest.h>

namespace microsim::sim {
namespace {

using testing::chain;
using testing::maxDistance;
using testing::paramsFor;
using testing::referenceOf;
using testing::topPull;

/// Iterations that take each solver close to equilibrium on the small meshes below.
int manyIterations(const std::string& name) {
  if (name == "newton" || name == "reference") return 50;
  if (name == "qss") return 3000;
  return 3000;  // cycles of 1/30 s of damped dynamics
}

class EverySolver : public ::testing::TestWithParam<std::string> {};

TEST_P(EverySolver, ChainPulledStretchesUniformly) {
  // n equal springs in series between a fixed end and a pulled end share the stretch
  const SpringModel model = chain(5, 10.0);
  SpringControls controls;
  controls.add(5, Vec3(7.5, 0, 0));
  SpringState state = SpringState::atRest(model);
  auto solver = makeSolver(GetParam(), paramsFor(GetParam()));
  SolveBudget budget;
  budget.maxIterations = manyIterations(GetParam()) * 4;
  budget.residualTolerance = 1e-9;
  const SolveReport r = solver->solve(model, state, controls, budget);
  EXPECT_EQ(r.status, SolveStatus::Converged);
  for (int i = 0; i <= 5; ++i) EXPECT_NEAR(state.x(0, i), 1.5 * i, 1e-6) << "node " << i;
  EXPECT_NEAR(state.x.row(1).norm() + state.x.row(2).norm(), 0.0, 1e-9);
}

TEST_P(EverySolver, TwoSpringSeriesMatchesClosedForm) {
  // 0 —k1— 1 —k2— 2 with 0 fixed at 0 and 2 pulled to L: node 1 sits where the tensions
  // balance, k1 (x − 1) = k2 (L − x − 1), x = (k1 + k2 (L − 1)) / (k1 + k2)
  SpringModel model;
  model.addNode(Vec3(0, 0, 0));
  model.addNode(Vec3(1, 0, 0));
  model.addNode(Vec3(2, 0, 0));
  model.addLink(0, 1, 10.0);
  model.addLink(1, 2, 40.0);
  model.setFixed(0);
  model.finalize();
  SpringControls controls;
  controls.add(2, Vec3(3.0, 0, 0));
  SpringState state = SpringState::atRest(model);
  auto solver = makeSolver(GetParam(), paramsFor(GetParam()));
  SolveBudget budget;
  budget.maxIterations = manyIterations(GetParam()) * 4;
  budget.residualTolerance = 1e-10;
  EXPECT_EQ(solver->solve(model, state, controls, budget).status, SolveStatus::Converged);
  EXPECT_NEAR(state.x(0, 1), (10.0 + 40.0 * 2.0) / 50.0, 1e-8);
}

TEST_P(EverySolver, HangingChainUnderGravityMatchesClosedForm) {
  // a vertical chain hung from node 0: spring s carries the weight of the nodes below it
  const int links = 4;
  SpringModel model;
  for (int i = 0; i <= links; ++i) model.addNode(Vec3(0, 0, -i));
  for (int i = 0; i < links; ++i) model.addLink(i, i + 1, 50.0);
  model.setFixed(0);
  model.gravity = Vec3(0, 0, -10.0);
  model.finalize();
  SpringState state = SpringState::atRest(model);
  auto solver = makeSolver(GetParam(), paramsFor(GetParam()));
  SolveBudget budget;
  budget.maxIterations = manyIterations(GetParam()) * 4;
  budget.residualTolerance = 1e-10;
  EXPECT_EQ(solver->solve(model, state, {}, budget).status, SolveStatus::Converged);
  double z = 0.0;
  for (int s = 0; s < links; ++s) {
    z -= 1.0 + (links - s) * 10.0 / 50.0;
    EXPECT_NEAR(state.x(2, s + 1), z, 1e-8);
  }
}

TEST_P(EverySolver, ConvergesToTheReferenceAndErrorFallsWithIterations) {
  const int n = 4;
  const SpringModel model = latticeBox(n, 10.0);
  const SpringControls controls = topPull(n, 1.0);
  const SpringState start = SpringState::atRest(model);
  const SpringState reference = referenceOf(model, start, controls);

  const int many = manyIterations(GetParam());
  double previous = 1e300;
  for (int iterations : {many / 50, many / 5, many}) {
    SpringState state = start;
    auto solver = makeSolver(GetParam(), paramsFor(GetParam()));
    SolveBudget budget;
    budget.maxIterations = std::max(iterations, 1);
    solver->solve(model, state, controls, budget);
    const double error = maxDistance(state.x, reference.x);
    EXPECT_TRUE(state.x.allFinite());
    EXPECT_LE(error, previous + 1e-9) << iterations << " iterations";
    previous = error;
  }
  EXPECT_LT(previous, 1e-6);
}

TEST_P(EverySolver, IsDeterministic) {
  const int n = 4;
  const SpringModel model = latticeBox(n, 10.0);
  const SpringControls controls = topPull(n, 0.7);
  std::uint64_t hashes[2];
  for (std::uint64_t& hash : hashes) {
    SpringState state = SpringState::atRest(model);
    auto solver = makeSolver(GetParam(), paramsFor(GetParam()));
    SolveBudget budget;
    budget.maxIterations = 7;
    for (int cycle = 0; cycle < 3; ++cycle) solver->solve(model, state, controls, budget);
    hash = stateHash(state);
  }
  EXPECT_EQ(hashes[0], hashes[1]);
}

INSTANTIATE_TEST_SUITE_P(Solvers, EverySolver,
                         ::testing::Values("qss", "rk4", "implicit", "newton", "reference"));

TEST(SolverRegistry, NamesAndUnknown) {
  for (const std::string& name : solverNames()) {
    auto solver = makeSolver(name);
    ASSERT_NE(solver, nullptr) << name;
    EXPECT_EQ(solver->name(), name);
  }
  EXPECT_EQ(makeSolver("nope"), nullptr);
}

TEST(Qss, CutoutWithZeroEpsilonIsBitIdentical) {
  const int n = 5;
  const SpringModel model = latticeBox(n, 10.0);
  const SpringControls controls = topPull(n, 1.0);
  SolverParams plain;
  SolverParams zero;
  zero.cutout = 0.0;
  SpringState a = SpringState::atRest(model);
  SpringState b = SpringState::atRest(model);
  SolveBudget budget;
  budget.maxIterations = 13;
  makeSolver("qss", plain)->solve(model, a, controls, budget);
  makeSolver("qss", zero)->solve(model, b, controls, budget);
  EXPECT_EQ(stateHash(a), stateHash(b));

  // a positive cutout changes the work, and the result stays close
  SolverParams cut;
  cut.cutout = 1e-3;
  SpringState c = SpringState::atRest(model);
  makeSolver("qss", cut)->solve(model, c, controls, budget);
  EXPECT_NE(stateHash(a), stateHash(c));
  EXPECT_LT(maxDistance(a.x, c.x), 0.05);
}

TEST(Qss, MomentumVariantConvergesFaster) {
  const int n = 5;
  const SpringModel model = latticeBox(n, 10.0);
  const SpringControls controls = topPull(n, 1.0);
  const SpringState reference = referenceOf(model, SpringState::atRest(model), controls);
  SolveBudget budget;
  budget.maxIterations = 60;
  SolverParams heavy;
  heavy.momentum = 0.6;
  SpringState plain = SpringState::atRest(model);
  SpringState withMomentum = SpringState::atRest(model);
  makeSolver("qss")->solve(model, plain, controls, budget);
  makeSolver("qss", heavy)->solve(model, withMomentum, controls, budget);
  EXPECT_LT(maxDistance(withMomentum.x, reference.x), maxDistance(plain.x, reference.x));
}

TEST(Newton, ActiveRegionGivesTheSameEquilibrium) {
  const int n = 6;
  const SpringModel model = latticeBox(n, 10.0);
  SpringState local = SpringState::atRest(model);
  SpringState whole = SpringState::atRest(model);
  SolverParams off;
  off.activeRegion = false;
  auto localSolver = makeSolver("newton");
  auto wholeSolver = makeSolver("newton", off);
  SolveBudget budget;
  budget.residualTolerance = 1e-9;
  for (int cycle = 1; cycle <= 3; ++cycle) {
    const SpringControls controls = topPull(n, cycle);
    EXPECT_EQ(localSolver->solve(model, local, controls, budget).status, SolveStatus::Converged);
    EXPECT_EQ(wholeSolver->solve(model, whole, controls, budget).status, SolveStatus::Converged);
    EXPECT_LT(maxDistance(local.x, whole.x), 1e-6) << "cycle " << cycle;
    EXPECT_LE(relativeResidual(model, local.x, controls), 1e-9);
  }
}

// two chains of three links along x, 0–3 at y = 0 and 4–7 at y = 5, each fixed at its start;
// a soft term pulls node 3 towards x = 3.2, and node 7 is pulled to x = 3 + `pull`
struct TwoChains {
  SpringModel model;
  SpringControls controls;
};

TwoChains twoChains(double pull) {
  TwoChains t;
  for (int i = 0; i < 8; ++i) t.model.addNode(Vec3(i % 4, i < 4 ? 0.0 : 5.0, 0.0));
  for (int c = 0; c < 2; ++c)
    for (int i = 0; i < 3; ++i) t.model.addLink(4 * c + i, 4 * c + i + 1, 10.0);
  t.model.setFixed(0);
  t.model.setFixed(4);
  t.model.finalize();
  t.controls.add(7, Vec3(3.0 + pull, 5.0, 0.0));
  PointSpring sp;
  sp.nodes = {3, -1, -1, -1};
  sp.weights = {1.0, 0.0, 0.0, 0.0};
  sp.anchor = Vec3(3.2, 0.0, 0.0);
  sp.k = 5.0;
  t.controls.springs.push_back(sp);
  return t;
}

TEST(Newton, APartInBalanceIsLeftWhereItIs) {
  // the region is every free node, in two parts that nothing couples: the chain that the
  // second pull does not reach stays as the first solve left it, to the bit
  const TwoChains first = twoChains(0.5);
  SpringState state = SpringState::atRest(first.model);
  auto newton = makeSolver("newton");
  SolveBudget budget;
  budget.residualTolerance = 1e-9;
  EXPECT_EQ(newton->solve(first.model, state, first.controls, budget).status,
            SolveStatus::Converged);
  const Points afterFirst = state.x;
  SpringControls second = first.controls;
  second.targets.col(0) = Vec3(3.8, 5.0, 0.0);
  const SolveReport r = newton->solve(first.model, state, second, budget);
  EXPECT_EQ(r.status, SolveStatus::Converged);
  EXPECT_GE(r.iterations, 1);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(state.x.col(i), afterFirst.col(i)) << "node " << i;
  EXPECT_LE(relativeResidual(first.model, state.x, second), 1e-9);
  // and both parts where the reference puts them
  EXPECT_LT(maxDistance(state.x, referenceOf(first.model, state, second).x), 1e-7);
}

}  // namespace
}  // namespace microsim::sim
