// qss: the paper's quasi-static solver (see solvers.h and node_ordering.h).
#include "microsim/sim/solve/node_ordering.h"
#include "microsim/sim/solve/spring_kernels.h"
#include "solve/solve_support.h"
#include "solve/solvers.h"

#include <algorithm>
#include <cmath>

namespace microsim::sim::detail {
namespace {

/// One alive link seen from one of its ends, packed for the sweep.
struct Neighbour {
  int node;
  double k;
  double rest;
  double c;  ///< stiffening coefficient
};

class QssSolver final : public TissueSolver {
 public:
  explicit QssSolver(const SolverParams& params) : params_(params) {}

  std::string_view name() const override { return "qss"; }
  void reset() override { key_ = {}; }

  SolveReport solve(const SpringModel& model, SpringState& state, const SpringControls& controls,
                    const SolveBudget& budget) override {
    Stopwatch clock;
    SolveReport report;
    if (!validInput(model, state, controls)) {
      report.status = SolveStatus::InvalidInput;
      return report;
    }
    const Points x0 = state.x;
    const Points v0 = state.v;
    applyControls(model, state, controls);
    prepare(model, controls);

    const double scale = forceScale(model, controls);
    const double tolerance = budget.residualTolerance * scale;
    const double beta = std::clamp(params_.momentum, 0.0, 0.999);
    const double eps = params_.cutout;
    const double omega = std::clamp(params_.relaxation, 1e-3, 1.99);
    const Vec3 g = model.gravity;
    Points& x = state.x;
    double start = -1.0;

    report.status = SolveStatus::IterationLimit;
    while (report.iterations < budget.maxIterations) {
      if (clock.seconds() >= budget.maxSeconds) {
        report.status = SolveStatus::TimeLimit;
        break;
      }
      // one sweep in wave order, level by level, with the cutout
      double worst = 0.0;
      const int levels = ordering_.levelCount();
      for (int level = 0; level < levels; ++level) {
        double moved = 0.0;
        for (int p = ordering_.levelStart[level]; p < ordering_.levelStart[level + 1]; ++p) {
          const int i = ordering_.order[p];
          const Vec3 xi = x.col(i);
          Vec3 f = model.mass(i) * g;
          double kd = 0.0;
          for (int e = start_[p]; e < start_[p + 1]; ++e) {
            const Neighbour& nb = neighbours_[e];
            const Vec3 d = x.col(nb.node) - xi;
            const double l = d.norm();
            if (l < kMinLength) {
              if (nb.rest <= kMinLength) f += nb.k * d;
              kd += nb.k;
              continue;
            }
            f += springTensionOverLength(nb.k, nb.rest, nb.c, l) * d;
            kd += springTensionDerivative(nb.k, nb.rest, nb.c, l);
          }
          worst = std::max(worst, f.squaredNorm());
          const double alpha = params_.alpha > 0.0 ? params_.alpha : (kd > 0.0 ? omega / kd : 0.0);
          Vec3 step = alpha * f;
          if (beta > 0.0) {
            step += beta * direction_.col(i);
            direction_.col(i) = step;
          }
          x.col(i) = xi + step;
          moved = std::max(moved, step.squaredNorm());
        }
        if (moved < eps * eps) break;
      }
      ++report.iterations;
      worst = std::sqrt(worst);
      report.residual = worst / scale;

      // divergence: restore the input
      if (start < 0.0) start = worst;
      if (!std::isfinite(worst) || worst > kDivergenceFactor * std::max(start, scale)) {
        state.x = x0;
        state.v = v0;
        report.status = SolveStatus::Diverged;
        report.seconds = clock.seconds();
        return report;
      }
      if (worst <= tolerance) {
        report.status = SolveStatus::Converged;
        break;
      }
    }
    state.v.setZero();
    report.seconds = clock.seconds();
    return report;
  }

 private:
  struct Key {
    const SpringModel* model = nullptr;
    int nodes = -1;
    int links = -1;
    int alive = -1;
    std::vector<int> seeds;
    bool operator==(const Key&) const = default;
  };

  /// NODE-ORDERING and the packed neighbour lists, redone only when the topology or the
  /// set of displaced control nodes changed.
  void prepare(const SpringModel& model, const SpringControls& controls) {
    Key key{&model, model.nodeCount(), model.linkCount(), model.aliveLinkCount(),
            activeControlNodes(model, controls)};
    if (key == key_) return;
    key_ = key;
    ordering_ = computeNodeOrdering(model, key_.seeds, freeMask(model, controls));
    start_.assign(1, 0);
    neighbours_.clear();
    for (int i : ordering_.order) {
      for (int li : model.linksOf(i)) {
        const Link& link = model.link(li);
        if (!link.alive) continue;
        neighbours_.push_back({model.otherEnd(li, i), link.k, link.rest, stiffeningCoefficient(link)});
      }
      start_.push_back(static_cast<int>(neighbours_.size()));
    }
    direction_ = Points::Zero(3, model.nodeCount());
  }

  SolverParams params_;
  Key key_;
  NodeOrdering ordering_;
  std::vector<int> start_;             ///< neighbours_ of order[p]: [start_[p], start_[p + 1])
  std::vector<Neighbour> neighbours_;
  Points direction_;                   ///< momentum: last step of every node (mm)
};

}  // namespace

std::unique_ptr<TissueSolver> makeQssSolver(const SolverParams& params) {
  return std::make_unique<QssSolver>(params);
}

}  // namespace microsim::sim::detail
