#include "microsim/sim/mesh/lattice.h"
#include "microsim/sim/solve/solver.h"

#include <gtest/gtest.h>

namespace microsim::sim {
namespace {

// a CPU-time budget ends an otherwise endless solve, for every solver, and says so
TEST(BudgetClock, ThreadCpuBudgetStopsEverySolver) {
  const SpringModel model = latticeBox(8, 10.0);
  for (const std::string& name : solverNames()) {
    if (name == "reference") continue;  // runs to its own tolerance by design
    auto solver = makeSolver(name);
    ASSERT_NE(solver, nullptr) << name;
    SpringState state = SpringState::atRest(model);
    SpringControls controls;
    const int top = latticeTopMiddle(8);
    controls.add(top, model.restPositions().col(top) + Vec3(0, 0, 1));
    SolveBudget budget;
    budget.maxSeconds = 50e-3;
    budget.clock = BudgetClock::ThreadCpu;
    const SolveReport report = solver->solve(model, state, controls, budget);
    EXPECT_TRUE(report.status == SolveStatus::TimeLimit || report.status == SolveStatus::Converged) << name;
    EXPECT_GT(report.iterations, 0) << name;
    EXPECT_TRUE(state.x.allFinite()) << name;
  }
}

}  // namespace
}  // namespace microsim::sim
