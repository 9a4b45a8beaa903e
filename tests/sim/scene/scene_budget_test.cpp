// The per-step budget through Scene in RealTime mode, on a fake clock: the tissue solve
// stops at its first check after the step's deadline, for every solver; in Deterministic
// mode the clock changes nothing.
#include "microsim/sim/mesh/lattice.h"
#include "microsim/sim/scene/scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <variant>

namespace microsim::sim {
namespace {

// advances a fixed step on every reading: each tissue iteration costs one step
struct FakeSceneClock {
  double step = 1e-3;  ///< s per reading
  double t = 0.0;
  double operator()() { return t += step; }
};

// an 8³ lattice pulled at the middle of its top face, which no solver finishes in a step
SceneDef pulledLattice(const std::string& solver, double budgetMs) {
  const int top = latticeTopMiddle(8);
  const std::string text = R"({"objects": [{"type": "lattice", "size": [8, 8, 8],
      "controls": [{"node": )" + std::to_string(top) + R"(, "displacement": [0, 0, 1]}]}],
    "solver": {"name": ")" + solver + R"(", "iterations": 1000, "tolerance": 0},
    "step": {"budget_ms": )" + std::to_string(budgetMs) + "}}";
  SceneDefLoad load = parseSceneDef(text);
  EXPECT_TRUE(std::holds_alternative<SceneDef>(load));
  return std::get<SceneDef>(std::move(load));
}

StepReport firstStep(const std::string& solver, double budgetMs, StepMode mode) {
  FakeSceneClock fake;
  Scene scene(pulledLattice(solver, budgetMs), mode, [&fake] { return fake(); });
  return scene.step(InputFrame{});
}

TEST(SceneBudget, RealTimeStopsTheTissueSolveAtTheFirstCheckAfterTheDeadline) {
  for (const char* solver : {"qss", "rk4", "implicit", "newton"}) {
    SCOPED_TRACE(solver);
    // the stages before the solve read the clock a fixed number of times, so each step
    // more of budget is exactly one more iteration
    const StepReport a = firstStep(solver, 30.5, StepMode::RealTime);
    const StepReport b = firstStep(solver, 33.5, StepMode::RealTime);
    EXPECT_EQ(a.tissue.status, SolveStatus::TimeLimit);
    EXPECT_EQ(b.tissue.status, SolveStatus::TimeLimit);
    EXPECT_GT(a.tissue.iterations, 0);
    EXPECT_EQ(b.tissue.iterations - a.tissue.iterations, 3);

    // a budget spent before the solve leaves it no iteration
    const StepReport none = firstStep(solver, 0.5, StepMode::RealTime);
    EXPECT_EQ(none.tissue.status, SolveStatus::TimeLimit);
    EXPECT_EQ(none.tissue.iterations, 0);

    // the stage times are read on the scene's clock
    EXPECT_GT(a.times.total, 0.03);
    EXPECT_NEAR(a.times.total / 1e-3, std::round(a.times.total / 1e-3), 1e-6);
  }
}

TEST(SceneBudget, DeterministicModeIgnoresTheClock) {
  const StepReport r = firstStep("qss", 0.5, StepMode::Deterministic);
  EXPECT_EQ(r.tissue.status, SolveStatus::IterationLimit);
  EXPECT_EQ(r.tissue.iterations, 1000);
}

}  // namespace
}  // namespace microsim::sim
