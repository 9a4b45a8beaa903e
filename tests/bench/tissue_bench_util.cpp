#include "tissue_bench_util.h"

#include <algorithm>
#include <cmath>

namespace microsim::bench {

using namespace microsim::sim;

SpringState referenceEquilibrium(const SpringModel& model, const SpringState& start,
                                 const SpringControls& controls) {
  SpringState s = start;
  makeSolver("reference")->solve(model, s, controls, {});
  return s;
}

namespace {

SpringControls pullTo(const SpringModel& model, int node, const Vec3& offset) {
  SpringControls c;
  c.add(node, model.restPositions().col(node) + offset);
  return c;
}

}  // namespace

PullCase coldPull(const std::string& name, const SpringModel& model, int node, const Vec3& step) {
  PullCase c;
  c.name = name;
  c.model = model;
  c.start = SpringState::atRest(c.model);
  c.controls = pullTo(c.model, node, step);
  c.displacement = step.norm();
  c.reference = referenceEquilibrium(c.model, c.start, c.controls);
  return c;
}

PullCase warmPull(const std::string& name, const SpringModel& model, int node, const Vec3& step) {
  PullCase c;
  c.name = name;
  c.model = model;
  c.start = referenceEquilibrium(c.model, SpringState::atRest(c.model), pullTo(c.model, node, step));
  c.controls = pullTo(c.model, node, 2.0 * step);
  c.previous = pullTo(c.model, node, step);
  c.displacement = step.norm();
  c.reference = referenceEquilibrium(c.model, c.start, c.controls);
  return c;
}

Errors errorsOf(const PullCase& c, const Points& x) {
  const Eigen::RowVectorXd d = (x - c.reference.x).colwise().norm();
  return {100.0 * d.maxCoeff() / c.displacement, 100.0 * d.mean() / c.displacement};
}

double ErrorCurve::timeTo(double percent) const {
  double best = -1.0;
  for (std::size_t i = 0; i < milliseconds.size(); ++i)
    if (maxPercent[i] <= percent && (best < 0.0 || milliseconds[i] < best)) best = milliseconds[i];
  return best;
}

SolverParams benchParams(const std::string& solverName) {
  SolverParams p;
  if (solverName == "rk4" || solverName == "implicit") p.damping = 6.0;
  if (solverName == "qss") p.relaxation = 1.7;
  return p;
}

ErrorCurve sweepErrorAgainstTime(const PullCase& c, const std::string& solverName,
                                 const SolverParams& params, double stopPercent, double capSeconds,
                                 int repeats) {
  ErrorCurve curve;
  const bool byTolerance = solverName == "newton";
  int iterations = 1, previous = 0;
  for (int step = 0; step < 200; ++step) {
    SolveBudget budget;
    if (byTolerance) {
      budget.residualTolerance = std::pow(10.0, -0.5 * (step + 2));
      if (budget.residualTolerance < 1e-11) break;
    } else {
      budget.maxIterations = iterations;
    }
    double best = 1e300;
    Points x;
    for (int r = 0; r < repeats; ++r) {
      auto solver = makeSolver(solverName, params);
      if (c.previous.size() > 0) {
        SpringState p = SpringState::atRest(c.model);
        solver->solve(c.model, p, c.previous, budget);
      }
      SpringState s = c.start;
      const double t0 = cpuSeconds();
      solver->solve(c.model, s, c.controls, budget);
      best = std::min(best, cpuSeconds() - t0);
      x = s.x;
      if (best > 0.02) break;  // long runs are measured once
    }
    const Errors e = errorsOf(c, x);
    curve.milliseconds.push_back(1e3 * best);
    curve.maxPercent.push_back(e.maxPercent);
    if (e.maxPercent <= stopPercent || best > capSeconds) break;
    // fibonacci-like growth of the iteration budget
    const int next = iterations + std::max(previous, 1);
    previous = iterations;
    iterations = next;
  }
  return curve;
}

}  // namespace microsim::bench
