// rk4: the paper's dynamic simulator, Eq. 1 by classical Runge–Kutta (see solvers.h).
#include "microsim/sim/solve/spring_kernels.h"
#include "solve/solve_support.h"
#include "solve/solvers.h"

#include <algorithm>
#include <cmath>

namespace microsim::sim::detail {
namespace {

class Rk4Solver final : public TissueSolver {
 public:
  explicit Rk4Solver(const SolverParams& params) : params_(params) {}
  std::string_view name() const override { return "rk4"; }

  SolveReport solve(const SpringModel& model, SpringState& state, const SpringControls& controls,
                    const SolveBudget& budget) override {
    Stopwatch clock(budget);
    SolveReport report;
    if (!validInput(model, state, controls)) {
      report.status = SolveStatus::InvalidInput;
      return report;
    }
    const Points x0 = state.x;
    const Points v0 = state.v;
    applyControls(model, state, controls);
    const int n = model.nodeCount();
    free_ = freeMask(model, controls);
    damping_.resize(n);
    for (int i = 0; i < n; ++i) damping_[i] = model.damping(i) + params_.damping;
    const double scale = forceScale(model, controls);
    const double tolerance = budget.residualTolerance * scale;
    const double cycle = params_.timeStep > 0.0 ? params_.timeStep : 1.0 / 30.0;

    double start = -1.0;
    report.status = SolveStatus::IterationLimit;
    while (true) {
      accelerations(model, state.x, state.v, ka_);
      const double residual = residualOf(model);
      report.residual = residual / scale;
      if (start < 0.0) start = residual;
      if (!std::isfinite(residual) || !allFinite(state.v) ||
          residual > kDivergenceFactor * std::max(start, scale)) {
        state.x = x0;
        state.v = v0;
        report.status = SolveStatus::Diverged;
        report.seconds = clock.seconds();
        return report;
      }
      if (residual <= tolerance) {
        report.status = SolveStatus::Converged;
        break;
      }
      if (report.iterations >= budget.maxIterations) break;
      if (clock.expired()) {
        report.status = SolveStatus::TimeLimit;
        break;
      }
      // one cycle in substeps below the stability limit
      const int substeps = std::max(1, static_cast<int>(std::ceil(cycle / stableStep(model, state.x))));
      const double h = cycle / substeps;
      for (int s = 0; s < substeps; ++s) rk4Step(model, state, h);
      ++report.iterations;
    }
    report.seconds = clock.seconds();
    return report;
  }

 private:
  /// Accelerations (3 by #N, mm/s²) of the free nodes; 0 for constrained ones. Keeps the
  /// spring-and-weight forces in force_ for the residual.
  void accelerations(const SpringModel& model, const Points& x, const Points& v, Points& a) {
    totalForces(model, x, force_);
    a.resize(3, model.nodeCount());
    for (int i = 0; i < model.nodeCount(); ++i) {
      if (!free_[i] || !(model.mass(i) > 0.0)) {
        a.col(i).setZero();
        continue;
      }
      a.col(i) = (force_.col(i) - damping_[i] * v.col(i)) / model.mass(i);
    }
  }

  double residualOf(const SpringModel& model) const {
    double worst = 0.0;
    for (int i = 0; i < model.nodeCount(); ++i)
      if (free_[i]) worst = std::max(worst, force_.col(i).norm());
    return worst;
  }

  /// The largest substep (s) that keeps RK4 stable on the stiffest free node.
  double stableStep(const SpringModel& model, const Points& x) const {
    std::vector<double> kd(static_cast<std::size_t>(model.nodeCount()), 0.0);
    for (const Link& link : model.links()) {
      if (!link.alive) continue;
      const double l = (x.col(link.b) - x.col(link.a)).norm();
      const double k = std::max(springTensionDerivative(link.k, link.rest, stiffeningCoefficient(link), l),
                                std::abs(springTensionOverLength(link.k, link.rest, stiffeningCoefficient(link),
                                                                 std::max(l, kMinLength))));
      kd[link.a] += std::min(k, 1e3 * link.k);
      kd[link.b] += std::min(k, 1e3 * link.k);
    }
    double h = params_.timeStep > 0.0 ? params_.timeStep : 1.0 / 30.0;
    for (int i = 0; i < model.nodeCount(); ++i) {
      if (!free_[i] || !(model.mass(i) > 0.0)) continue;
      if (kd[i] > 0.0) h = std::min(h, std::sqrt(model.mass(i) / (2.0 * kd[i])));
      if (damping_[i] > 0.0) h = std::min(h, model.mass(i) / damping_[i]);
    }
    return h;
  }

  void rk4Step(const SpringModel& model, SpringState& s, double h) {
    x1_ = s.x;
    v1_ = s.v;
    accelerations(model, x1_, v1_, ka_);
    kv_ = v1_;
    // stage 2
    xs_ = x1_ + 0.5 * h * kv_;
    vs_ = v1_ + 0.5 * h * ka_;
    accelerations(model, xs_, vs_, a2_);
    // stage 3
    xs_ = x1_ + 0.5 * h * vs_;
    v2_ = vs_;
    vs_ = v1_ + 0.5 * h * a2_;
    accelerations(model, xs_, vs_, a3_);
    // stage 4
    xs_ = x1_ + h * vs_;
    v3_ = vs_;
    vs_ = v1_ + h * a3_;
    accelerations(model, xs_, vs_, a4_);
    // combine; constrained nodes have zero velocity and acceleration throughout
    s.x = x1_ + (h / 6.0) * (kv_ + 2.0 * v2_ + 2.0 * v3_ + vs_);
    s.v = v1_ + (h / 6.0) * (ka_ + 2.0 * a2_ + 2.0 * a3_ + a4_);
  }

  SolverParams params_;
  std::vector<unsigned char> free_;
  std::vector<double> damping_;
  Points force_, ka_, kv_, a2_, a3_, a4_, x1_, v1_, v2_, v3_, xs_, vs_;
};

}  // namespace

std::unique_ptr<TissueSolver> makeRk4Solver(const SolverParams& params) {
  return std::make_unique<Rk4Solver>(params);
}

}  // namespace microsim::sim::detail
