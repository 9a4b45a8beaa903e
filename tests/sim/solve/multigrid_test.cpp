// The smoothed-aggregation multigrid preconditioner: a valid (symmetric, positive)
// preconditioner that makes CG converge in few iterations, independent of stiffness
// ratio, and the newton solver's equilibrium with it equals the reference.
#include "microsim/sim/mesh/lattice.h"
#include "microsim/sim/solve/solver.h"
#include "microsim/sim/solve/spring_kernels.h"
#include "solve/block_system.h"
#include "solve/multigrid.h"
#include "solve_test_util.h"

#include <gtest/gtest.h>

namespace microsim::sim::detail {
namespace {

/// The clamped Hessian of the free nodes of `model` at x, and their positions.
BlockSystem hessianOf(const SpringModel& model, const Points& x, const SpringControls& controls,
                      Eigen::Matrix3Xd& positions) {
  const std::vector<unsigned char> free = freeMask(model, controls);
  std::vector<int> local(static_cast<std::size_t>(model.nodeCount()), -1);
  int m = 0;
  for (int i = 0; i < model.nodeCount(); ++i)
    if (free[i]) local[i] = m++;
  BlockSystem system;
  system.clear(m);
  positions.resize(3, m);
  for (int i = 0; i < model.nodeCount(); ++i)
    if (local[i] >= 0) positions.col(local[i]) = x.col(i);
  for (const Link& link : model.links()) {
    const Eigen::Matrix3d h = linkHessian(link, x.col(link.a), x.col(link.b), true);
    const int a = local[link.a], b = local[link.b];
    if (a >= 0) system.diag[a] += h;
    if (b >= 0) system.diag[b] += h;
    if (a >= 0 && b >= 0) system.off.push_back({a, b, SymBlock::from(-h)});
  }
  return system;
}

/// A 10³ box whose lower half is 1000 times stiffer than its upper half.
SpringModel stiffRatioBox(int n) {
  const SpringModel box = latticeBox(n, 10.0);
  SpringModel model;
  for (int i = 0; i < box.nodeCount(); ++i) model.addNode(box.restPositions().col(i));
  const double mid = 0.5 * (n - 1);
  for (const Link& l : box.links()) {
    const bool lower = box.restPositions()(2, l.a) < mid && box.restPositions()(2, l.b) < mid;
    model.addLink(l.a, l.b, lower ? 1e4 : 10.0);
  }
  for (int i : box.fixedNodes()) model.setFixed(i);
  model.finalize();
  return model;
}

TEST(BlockSystem, SparseFormEqualsBlockProduct) {
  const SpringModel model = latticeBox(4, 10.0);
  Eigen::Matrix3Xd positions;
  const BlockSystem system = hessianOf(model, SpringState::atRest(model).x, {}, positions);
  const Eigen::VectorXd p = Eigen::VectorXd::LinSpaced(3 * system.size(), -1.0, 2.0);
  Eigen::VectorXd y;
  system.multiply(p, y);
  const Eigen::VectorXd z = system.toSparse() * p;
  EXPECT_LT((y - z).norm(), 1e-12 * y.norm());
}

TEST(Multigrid, IsSymmetricAndPositive) {
  const SpringModel model = latticeBox(8, 10.0);
  Eigen::Matrix3Xd positions;
  const BlockSystem system =
      hessianOf(model, SpringState::atRest(model).x, testing::topPull(8, 1.0), positions);
  AggregationMultigrid mg;
  ASSERT_TRUE(mg.build(system, positions));
  EXPECT_GE(mg.levelCount(), 2);
  const int n = 3 * system.size();
  Eigen::VectorXd u(n), v(n), mu, mv;
  for (int i = 0; i < n; ++i) {
    u[i] = std::sin(0.37 * i);
    v[i] = std::cos(0.11 * i * i);
  }
  mg.apply(u, mu);
  mg.apply(v, mv);
  EXPECT_NEAR(u.dot(mv), v.dot(mu), 1e-10 * std::abs(u.dot(mv)) + 1e-14);
  EXPECT_GT(u.dot(mu), 0.0);
  EXPECT_GT(v.dot(mv), 0.0);
}

TEST(Multigrid, CgConvergesInFewIterationsWhateverTheStiffnessRatio) {
  for (const bool stiff : {false, true}) {
    const SpringModel model = stiff ? stiffRatioBox(10) : latticeBox(10, 10.0);
    Eigen::Matrix3Xd positions;
    const BlockSystem system =
        hessianOf(model, SpringState::atRest(model).x, testing::topPull(10, 1.0), positions);
    AggregationMultigrid mg;
    ASSERT_TRUE(mg.build(system, positions));
    Eigen::VectorXd b = Eigen::VectorXd::Zero(3 * system.size());
    for (int i = 0; i < b.size(); ++i) b[i] = std::sin(0.1 * i);
    Eigen::VectorXd x, y;
    const PcgResult withMg = solvePcg(system, mg, b, x, 1e-8, 200);
    EXPECT_TRUE(withMg.ok);
    EXPECT_LE(withMg.relativeResidual, 1e-8);
    system.multiply(x, y);
    EXPECT_LT((y - b).norm(), 1e-7 * b.norm());
    const PcgResult jacobi = solvePcg(system, b, x, 1e-8, 5000);
    EXPECT_LT(withMg.iterations * 4, jacobi.iterations) << (stiff ? "1000:1" : "uniform");
    EXPECT_LE(withMg.iterations, 30) << (stiff ? "1000:1" : "uniform");
  }
}

TEST(Multigrid, NewtonWithMultigridReachesTheReference) {
  // 10³ has 900 free nodes, under the 2000 where newton turns to multigrid: it solves
  // with its direct path, and must reach the same equilibrium
  const int n = 10;
  const SpringModel model = stiffRatioBox(n);
  const SpringControls controls = testing::topPull(n, 2.0);
  const SpringState start = SpringState::atRest(model);
  const SpringState reference = testing::referenceOf(model, start, controls);
  SpringState state = start;
  SolverParams params;
  params.activeRegion = false;
  SolveBudget budget;
  budget.residualTolerance = 1e-9;
  const SolveReport r = makeSolver("newton", params)->solve(model, state, controls, budget);
  EXPECT_EQ(r.status, SolveStatus::Converged);
  EXPECT_LT(testing::maxDistance(state.x, reference.x), 1e-6);
}

TEST(Multigrid, NewtonOnALargeRegionConvergesInFewIterationsPokedOrPulled) {
  // 14³ has 2548 free nodes, past the 2000 where newton turns to multigrid-preconditioned
  // CG. The top middle node poked 3 down compresses the links below it (the true Hessian is
  // indefinite there) or pulled 6 up stretches them. CG on the true Hessian, truncated at
  // negative curvature, converges in 5 Newton iterations either way; on its projection it
  // took 31 poked and 11 pulled (linear convergence).
  const int n = 14;
  const SpringModel model = latticeBox(n, 10.0);
  for (const double d : {-3.0, 6.0}) {
    SCOPED_TRACE(d);
    const SpringControls controls = testing::topPull(n, d);
    SpringState state = SpringState::atRest(model);
    SolverParams params;
    params.activeRegion = false;
    SolveBudget budget;
    budget.residualTolerance = 1e-9;
    budget.maxIterations = 100;
    const SolveReport r = makeSolver("newton", params)->solve(model, state, controls, budget);
    EXPECT_EQ(r.status, SolveStatus::Converged);
    EXPECT_LE(r.iterations, 8);
    const SpringState reference = testing::referenceOf(model, SpringState::atRest(model), controls);
    EXPECT_LT(testing::maxDistance(state.x, reference.x), 1e-6);
  }
}

TEST(Multigrid, KeptHierarchyServesTheNextCycles) {
  // a persistent newton solver over cycles of the paper's protocol converges every cycle
  const int n = 10;
  const SpringModel model = latticeBox(n, 10.0);
  auto solver = makeSolver("newton");
  SpringState state = SpringState::atRest(model);
  for (int cycle = 1; cycle <= 3; ++cycle) {
    const SpringControls controls = testing::topPull(n, cycle);
    SolveBudget budget;
    budget.residualTolerance = 1e-9;
    const SolveReport r = solver->solve(model, state, controls, budget);
    EXPECT_EQ(r.status, SolveStatus::Converged) << "cycle " << cycle;
    const SpringState reference = testing::referenceOf(model, state, controls);
    EXPECT_LT(testing::maxDistance(state.x, reference.x), 1e-6) << "cycle " << cycle;
  }
}

}  // namespace
}  // namespace microsim::sim::detail
