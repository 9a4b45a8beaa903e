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

// a fake clock that advances a fixed step on every reading; a solver reads it once at its
// start, once per iteration (the check) and once at its end, so every iteration costs one step
struct FakeClock {
  double step = 1e-3;  ///< s per reading
  double t = 0.0;
  int reads = 0;
  double operator()() {
    ++reads;
    return t += step;
  }
};

// with a budget of k.5 steps the solve stops at the first check after it: k iterations
TEST(BudgetClock, EverySolverStopsAtTheFirstCheckAfterTheBudget) {
  const SpringModel model = latticeBox(8, 10.0);
  const int top = latticeTopMiddle(8);
  for (const std::string& name : solverNames()) {
    if (name == "reference") continue;  // runs to its own tolerance by design
    for (int k : {0, 1, 3, 6}) {
      SCOPED_TRACE(name + " k=" + std::to_string(k));
      auto solver = makeSolver(name);
      SpringState state = SpringState::atRest(model);
      SpringControls controls;
      controls.add(top, model.restPositions().col(top) + Vec3(0, 0, 1));
      FakeClock fake;
      SolveBudget budget;
      budget.maxIterations = 1000;
      budget.maxSeconds = (k + 0.5) * fake.step;
      budget.now = [&fake] { return fake(); };
      const SolveReport report = solver->solve(model, state, controls, budget);
      EXPECT_EQ(report.status, SolveStatus::TimeLimit);
      EXPECT_EQ(report.iterations, k);
      EXPECT_EQ(fake.reads, k + 3);  // start, k + 1 checks, end
      EXPECT_NEAR(report.seconds, (k + 2) * fake.step, 1e-12);
    }
  }
}

// a deadline set before the solve (SolveBudget::since) counts the time spent before it
TEST(BudgetClock, ADeadlineFromBeforeTheSolveCountsTheTimeAlreadySpent) {
  const SpringModel model = latticeBox(6, 10.0);
  const int top = latticeTopMiddle(6);
  auto solver = makeSolver("newton");
  SpringState state = SpringState::atRest(model);
  SpringControls controls;
  controls.add(top, model.restPositions().col(top) + Vec3(0, 0, 1));
  FakeClock fake;
  SolveBudget budget;
  budget.since = 0.0;
  fake.t = 10 * fake.step;  // ten steps spent before the solve
  budget.maxSeconds = 12.5 * fake.step;
  budget.now = [&fake] { return fake(); };
  const SolveReport report = solver->solve(model, state, controls, budget);
  EXPECT_EQ(report.status, SolveStatus::TimeLimit);
  EXPECT_EQ(report.iterations, 1);  // start at 11, checks at 12 (go) and 13 (stop)
}

}  // namespace
}  // namespace microsim::sim
