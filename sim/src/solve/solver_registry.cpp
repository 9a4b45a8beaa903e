#include "microsim/sim/solve/solver.h"

#include "solve/solvers.h"

namespace microsim::sim {

std::unique_ptr<TissueSolver> makeSolver(std::string_view name, const SolverParams& params) {
  if (name == "qss") return detail::makeQssSolver(params);
  if (name == "rk4") return detail::makeRk4Solver(params);
  if (name == "implicit") return detail::makeImplicitSolver(params);
  if (name == "newton") return detail::makeNewtonSolver(params, false);
  if (name == "reference") return detail::makeNewtonSolver(params, true);
  return nullptr;
}

std::vector<std::string> solverNames() { return {"qss", "rk4", "implicit", "newton", "reference"}; }

}  // namespace microsim::sim
