// implicit: linearised backward Euler with block-Jacobi CG (see solvers.h).
#include "microsim/sim/solve/spring_kernels.h"
#include "solve/block_system.h"
#include "solve/solve_support.h"
#include "solve/solvers.h"

#include <algorithm>
#include <cmath>

namespace microsim::sim::detail {
namespace {

class ImplicitSolver final : public TissueSolver {
 public:
  explicit ImplicitSolver(const SolverParams& params) : params_(params) {}
  std::string_view name() const override { return "implicit"; }

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
    const std::vector<unsigned char> free = freeMask(model, controls);
    // unknowns: the free nodes
    local_.assign(static_cast<std::size_t>(n), -1);
    nodes_.clear();
    for (int i = 0; i < n; ++i)
      if (free[i]) {
        local_[i] = static_cast<int>(nodes_.size());
        nodes_.push_back(i);
      }
    const int m = static_cast<int>(nodes_.size());
    const double scale = forceScale(model, controls);
    const double tolerance = budget.residualTolerance * scale;
    const double h = params_.timeStep > 0.0 ? params_.timeStep : 1.0 / 30.0;
    const double eta = params_.linearTolerance > 0.0 ? params_.linearTolerance : 1e-4;

    double start = -1.0;
    report.status = SolveStatus::IterationLimit;
    while (true) {
      totalForces(model, state.x, force_);
      double residual = 0.0;
      for (int i : nodes_) residual = std::max(residual, force_.col(i).norm());
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

      // (M + hC + h²K) Δv = h (f − C v) − h² K v
      system_.clear(m);
      rhs_.resize(3 * m);
      for (int r = 0; r < m; ++r) {
        const int i = nodes_[r];
        const double c = model.damping(i) + params_.damping;
        system_.diag[r] = (model.mass(i) + h * c) * Eigen::Matrix3d::Identity();
        rhs_.segment<3>(3 * r) = h * (force_.col(i) - c * state.v.col(i));
      }
      for (const Link& link : model.links()) {
        if (!link.alive) continue;
        const int ra = local_[link.a];
        const int rb = local_[link.b];
        if (ra < 0 && rb < 0) continue;
        const Eigen::Matrix3d k =
            (h * h) * linkHessian(link, state.x.col(link.a), state.x.col(link.b), true);
        // −h² K v for the rows of a and b
        const Vec3 dv = state.v.col(link.a) - state.v.col(link.b);
        if (ra >= 0) {
          system_.diag[ra] += k;
          rhs_.segment<3>(3 * ra) -= k * dv;
        }
        if (rb >= 0) {
          system_.diag[rb] += k;
          rhs_.segment<3>(3 * rb) += k * dv;
        }
        if (ra >= 0 && rb >= 0) system_.off.push_back({ra, rb, SymBlock::from(-k)});
      }
      solvePcg(system_, rhs_, dv_, eta, std::max(25, std::min(3 * m, 200)));
      if (!dv_.allFinite()) dv_.setZero();
      for (int r = 0; r < m; ++r) {
        const int i = nodes_[r];
        state.v.col(i) += dv_.segment<3>(3 * r);
        state.x.col(i) += h * state.v.col(i);
      }
      ++report.iterations;
    }
    report.seconds = clock.seconds();
    return report;
  }

 private:
  SolverParams params_;
  std::vector<int> local_, nodes_;
  BlockSystem system_;
  Points force_;
  Eigen::VectorXd rhs_, dv_;
};

}  // namespace

std::unique_ptr<TissueSolver> makeImplicitSolver(const SolverParams& params) {
  return std::make_unique<ImplicitSolver>(params);
}

}  // namespace microsim::sim::detail
