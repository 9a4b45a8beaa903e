#pragma once
// Shared by the tissue benchmarks (table1, fig5, speed-error): the paper's pull protocol,
// the paper's error metric, and "time to reach an error" measured by sweeping budgets.
//
// Error (DESIGN.md): node distances to the reference equilibrium (the `reference`
// solver, relative residual 1e-10), max and mean over all nodes, divided by the size of
// the control displacement of the cycle being solved, in %.

#include "bench_clock.h"
#include "bench_report.h"

#include "microsim/sim/solve/solver.h"

#include <functional>
#include <string>
#include <vector>

namespace microsim::bench {

/// One pull: a model, the node a tool holds, where it starts (the start state) and
/// where the cycle moves it.
struct PullCase {
  std::string name;
  sim::SpringModel model;
  sim::SpringState start;      ///< warm: the previous cycle's equilibrium; cold: rest
  sim::SpringControls controls;  ///< this cycle's targets
  double displacement = 1.0;   ///< how far the control moves this cycle (mm)
  sim::SpringState reference;  ///< the equilibrium of this cycle
  /// warm: the previous cycle's targets, which every measured solver first solves itself
  /// from rest (untimed) so that its caches are those of a running simulation; cold: none
  sim::SpringControls previous;
};

/// Builds warm and cold cases of pulling `node` by `step` from rest (cold: rest → step;
/// warm: equilibrium at step → 2·step), with their references.
PullCase coldPull(const std::string& name, const sim::SpringModel& model, int node,
                  const sim::Vec3& step);
PullCase warmPull(const std::string& name, const sim::SpringModel& model, int node,
                  const sim::Vec3& step);

/// Max and mean node distance of x to the case's reference, in % of the displacement.
struct Errors {
  double maxPercent = 0.0;
  double meanPercent = 0.0;
};
Errors errorsOf(const PullCase& c, const sim::Points& x);

/// The reference equilibrium of `controls` from `start`.
sim::SpringState referenceEquilibrium(const sim::SpringModel& model, const sim::SpringState& start,
                                      const sim::SpringControls& controls);

/// A solver's error against its cost: one point per budget tried.
struct ErrorCurve {
  std::vector<double> milliseconds;
  std::vector<double> maxPercent;
  /// The least time (ms) at which the max error is ≤ percent, or a negative number
  /// when no budget reached it.
  double timeTo(double percent) const;
};

/// Runs `solverName` from the case's start with growing budgets (iterations 1, 2, 3, 5,
/// 8, ... for the iterative solvers, residual tolerances 10^(-j/2) for newton), each
/// from a fresh solver and a copy of the start, until the error reaches `stopPercent`
/// or one run takes longer than `capSeconds`. Times are the best of `repeats` runs, in
/// CPU time of the measuring thread (cpuSeconds), so that other load on the machine does
/// not count. Warm cases first run the previous cycle through the same solver with the
/// same budget, untimed, as a simulation running at that budget would have (newton's
/// active region and multigrid hierarchy, qss's NODE-ORDERING); the state is then set
/// to the case's start, the previous cycle's exact equilibrium.
ErrorCurve sweepErrorAgainstTime(const PullCase& c, const std::string& solverName,
                                 const sim::SolverParams& params, double stopPercent,
                                 double capSeconds, int repeats);

/// The parameters each solver runs with in the benchmarks (documented in the README):
/// qss as the paper, rk4 and implicit with damping that settles the box fastest.
sim::SolverParams benchParams(const std::string& solverName);

}  // namespace microsim::bench
