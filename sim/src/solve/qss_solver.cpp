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
  Stiffening c;  ///< stiffening terms (spring_kernels.h)
};

class QssSolver final : public TissueSolver {
 public:
  explicit QssSolver(const SolverParams& params) : params_(params) {}

  std::string_view name() const override { return "qss"; }
  void reset() override { key_ = {}; }

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
    prepare(model, controls);

    const double scale = forceScale(model, controls);
    const double tolerance = budget.residualTolerance * scale;
    const double beta = std::clamp(params_.momentum, 0.0, 0.999);
    const double eps = params_.cutout;
    const double omega = std::clamp(params_.relaxation, 1e-3, 1.99);
    const Vec3 g = model.gravity;
    Points& x = state.x;
    const std::vector<double>& mg = model.masses();
    double start = -1.0;

    report.status = SolveStatus::IterationLimit;
    // the clock is read before the first sweep and then every kClockStride node updates,
    // so that sweeps cut down to a few nodes are not dominated by reading it
    constexpr long kClockStride = 256;
    long work = kClockStride;
    while (report.iterations < budget.maxIterations) {
      if (work >= kClockStride) {
        work = 0;
        if (clock.expired()) {
          report.status = SolveStatus::TimeLimit;
          break;
        }
      }
      // one sweep in wave order, level by level, with the cutout
      double worst = 0.0;
      const int levels = ordering_.levelCount();
      for (int level = 0; level < levels; ++level) {
        double moved = 0.0;
        for (int p = ordering_.levelStart[level]; p < ordering_.levelStart[level + 1]; ++p) {
          const int i = ordering_.order[p];
          const double* xi = x.data() + 3 * i;
          const double xi0 = xi[0], xi1 = xi[1], xi2 = xi[2];
          double f0 = mg[i] * g.x(), f1 = mg[i] * g.y(), f2 = mg[i] * g.z();
          double kd = 0.0;
          const bool linear = linear_[p];
          if (linear) {
            // constant-law links: T / l = k (l − r) / l (the same arithmetic as the kernel)
            for (int e = start_[p]; e < start_[p + 1]; ++e) {
              const Neighbour& nb = neighbours_[e];
              const double* xj = x.data() + 3 * nb.node;
              const double d0 = xj[0] - xi0, d1 = xj[1] - xi1, d2 = xj[2] - xi2;
              const double l = std::sqrt(d0 * d0 + d1 * d1 + d2 * d2);
              const double s = l < kMinLength ? (nb.rest <= kMinLength ? nb.k : 0.0)
                                              : nb.k * (l - nb.rest) / l;
              f0 += s * d0;
              f1 += s * d1;
              f2 += s * d2;
            }
            kd = linearStiffness_[p];
          } else {
            for (int e = start_[p]; e < start_[p + 1]; ++e) {
              const Neighbour& nb = neighbours_[e];
              const double* xj = x.data() + 3 * nb.node;
              const double d0 = xj[0] - xi0, d1 = xj[1] - xi1, d2 = xj[2] - xi2;
              const double l = std::sqrt(d0 * d0 + d1 * d1 + d2 * d2);
              double s;
              if (l < kMinLength) {
                s = nb.rest <= kMinLength ? nb.k : 0.0;
                kd += nb.k;
              } else {
                s = springTensionOverLength(nb.k, nb.rest, nb.c, l);
                kd += springTensionDerivative(nb.k, nb.rest, nb.c, l);
              }
              f0 += s * d0;
              f1 += s * d1;
              f2 += s * d2;
            }
          }
          const Vec3 f(f0, f1, f2);
          worst = std::max(worst, f.squaredNorm());
          const double alpha = params_.alpha > 0.0 ? params_.alpha : (kd > 0.0 ? omega / kd : 0.0);
          Vec3 step = alpha * f;
          if (beta > 0.0) {
            step += beta * direction_.col(i);
            direction_.col(i) = step;
          }
          x.col(i) = Vec3(xi0, xi1, xi2) + step;
          moved = std::max(moved, step.squaredNorm());
        }
        work += ordering_.levelStart[level + 1] - ordering_.levelStart[level];
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
    linear_.clear();
    linearStiffness_.clear();
    for (int i : ordering_.order) {
      // constant-law links have T' = k: their node's Σ T' is fixed
      bool linear = true;
      double kSum = 0.0;
      for (int li : model.linksOf(i)) {
        const Link& link = model.link(li);
        if (!link.alive) continue;
        neighbours_.push_back({model.otherEnd(li, i), link.k, link.rest, stiffeningCoefficient(link)});
        linear = linear && neighbours_.back().c.linear();
        kSum += link.k;
      }
      start_.push_back(static_cast<int>(neighbours_.size()));
      linear_.push_back(linear ? 1 : 0);
      linearStiffness_.push_back(kSum);
    }
    direction_ = Points::Zero(3, model.nodeCount());
  }

  SolverParams params_;
  Key key_;
  NodeOrdering ordering_;
  std::vector<int> start_;             ///< neighbours_ of order[p]: [start_[p], start_[p + 1])
  std::vector<Neighbour> neighbours_;
  std::vector<unsigned char> linear_;  ///< per order position: every link has T' = k
  std::vector<double> linearStiffness_;  ///< per order position: Σ k of its links
  Points direction_;                   ///< momentum: last step of every node (mm)
};

}  // namespace

std::unique_ptr<TissueSolver> makeQssSolver(const SolverParams& params) {
  return std::make_unique<QssSolver>(params);
}

}  // namespace microsim::sim::detail
