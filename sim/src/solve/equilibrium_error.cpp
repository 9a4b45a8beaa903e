#include "microsim/sim/solve/equilibrium_error.h"

#include "microsim/sim/solve/solver.h"

#include <algorithm>

namespace microsim::sim {

EquilibriumError equilibriumError(const SpringModel& model, const SpringState& state,
                                  const SpringControls& controls) {
  EquilibriumError e;

  // the converged equilibrium, warm-started from a copy of the state
  SpringState reference = state;
  const SolveReport report = makeSolver("reference")->solve(model, reference, controls, {});
  e.converged = report.status == SolveStatus::Converged;
  if (reference.x.cols() == state.x.cols() && state.x.cols() > 0)
    e.maxDistance = (state.x - reference.x).colwise().norm().maxCoeff();

  // the largest control displacement from rest
  const auto rest = model.restPositions();
  for (int c = 0; c < controls.size(); ++c) {
    const int node = controls.nodes[static_cast<std::size_t>(c)];
    e.controlDisplacement = std::max(e.controlDisplacement, (controls.targets.col(c) - rest.col(node)).norm());
  }
  // a two-sided point spring pulls its point towards its anchor (a thread through a pierce):
  // its anchor's distance from the point's rest position is a control displacement too
  for (const PointSpring& s : controls.springs)
    if (!s.oneSided()) e.controlDisplacement = std::max(e.controlDisplacement, pointSpringOffset(s, rest).norm());
  if (e.controlDisplacement > 0.0) e.ratioPercent = 100.0 * e.maxDistance / e.controlDisplacement;
  return e;
}

}  // namespace microsim::sim
