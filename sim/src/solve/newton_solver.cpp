// newton and reference: equilibrium by Newton–PCG (see solvers.h).
//
// The active region. A pull on a big mesh should cost what it costs on a small one, so
// the unknowns are only the free nodes the pull reaches, a region R that grows as the
// wave spreads:
//  - seeds: the region of the last solve when the same control nodes pull on the same
//    topology (the pull will reach as far again, and the multigrid hierarchy built for
//    that region still fits); then, when the state is bit-identical to what this solver
//    returned last time, the free neighbours of the control nodes that moved since
//    (plus the previous region if that solve stopped short of its tolerance); otherwise
//    (first call, someone else moved nodes, a cut) one full force pass, and every free
//    node whose |f_i| exceeds the threshold;
//  - R = the seeds plus two breadth-first layers of free nodes;
//  - every iteration the boundary B (free nodes next to R, outside it) is checked; nodes of
//    B whose |f_i| exceeds the threshold join R with 2^g further layers (g = growths so far),
//    so that a wave crossing L levels costs O(log L) growths;
//  - a region over half the free nodes takes them all, in node order (it saves little, and
//    a region that is always the same list keeps its multigrid hierarchy from cycle to
//    cycle; the hierarchies of the last two regions are kept, so a pull that comes and goes
//    between steps, changing the free nodes, does not rebuild one every step);
//  - nodes outside R ∪ B keep the forces they had, which the previous solve left below
//    the threshold, so max over R ∪ B is the residual of the whole mesh.
// The threshold is the budget's residual tolerance times forceScale. Nodes outside R are
// held where they are during a step, as if fixed; the result is exact once R stops growing.
//
// Parts. When R is every free node and small enough for the direct path, it may fall into
// parts that nothing couples: no alive link and no soft term joins them (region_parts.h; the
// stitch's two cut ends, 192 free nodes each). Their Hessian is block diagonal and their
// energies add up, so each part is solved as a problem of its own, one after the other, with
// its own kept factorisation: a part in balance costs one residual pass, and a part that needs
// another iteration or a new factorisation does not take the other along. (Solved together,
// the stitch's punctures and pulls iterated and factorised both ends while one of them had
// been in balance since the first or second iteration.) The solve's iterations are those of
// the part that took the most. What it gives up: a part is no longer carried past the
// tolerance by the iterations of another, so it ends nearer the tolerance than it did.
#include "microsim/sim/solve/spring_kernels.h"
#include "solve/block_system.h"
#include "solve/link_terms.h"
#include "solve/multigrid.h"
#include "solve/region_parts.h"
#include "solve/solve_support.h"
#include "solve/solvers.h"
#include "solve/supernodal_cholesky.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

namespace microsim::sim::detail {
namespace {

constexpr double kReferenceTolerance = 1e-10;
/// Regions of at least this many nodes are solved with the multigrid preconditioner, smaller
/// ones by a sparse Cholesky factorisation (exact Newton directions; the fill of a tube's mesh is
/// small at this size).
constexpr int kMultigridNodes = 2000;
/// CG iterations above which the multigrid hierarchy is rebuilt for the next step.
constexpr int kRebuildIterations = 25;
/// CG iterations, preconditioned by an earlier factorisation, above which the region's
/// Hessian is factorised anew.
constexpr int kRefactorIterations = 12;
/// CG iterations of the last solve with the kept factors above which the next direction
/// factorises anew rather than try them again: factors that needed this many have gone stale
/// (the Hessian moved on: contact, the turning needle), and each further try costs more CG
/// iterations than a factorisation (~10 CG iterations' worth on the stitch's 384 nodes:
/// 0.55 ms against 0.04 ms a solve and 0.017 ms a product) saves.
constexpr int kStaleIterations = 4;

/// An earlier Cholesky factorisation of the region's Hessian as the preconditioner of CG on the
/// current one: a pull that changes the Hessian a little costs a few solves with the old
/// factors instead of a new factorisation (most steps of a stitch).
class FactorPreconditioner final : public Preconditioner {
 public:
  explicit FactorPreconditioner(const SupernodalCholesky& f) : factors_(f) {}
  void apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const override { factors_.solve(r, z); }

 private:
  const SupernodalCholesky& factors_;
};

/// A multigrid hierarchy and what it was built for.
struct Hierarchy {
  AggregationMultigrid multigrid;
  const SpringModel* model = nullptr;
  int links = -1, alive = -1;
  std::vector<int> region;
  long lastUse = 0;
};

/// A factorisation kept for the next directions, and what it was made for.
struct KeptFactors {
  SupernodalCholesky cholesky;
  bool valid = false;
  int lastPcgIterations = 0;  ///< of the last CG solve preconditioned by these factors
  std::vector<int> region;
  int alive = -1;
};

class NewtonSolver final : public TissueSolver {
 public:
  NewtonSolver(const SolverParams& params, bool reference)
      : params_(params), reference_(reference) {}

  std::string_view name() const override { return reference_ ? "reference" : "newton"; }
  bool supportsPointSprings() const override { return true; }
  void reset() override {
    lastModel_ = nullptr;
    lastX_.resize(3, 0);
    lastRegion_.clear();
    lastMovers_.clear();
    for (Hierarchy& h : hierarchies_) h.region.clear();
    for (KeptFactors& k : kept_) k.valid = false;
    linkSetsModel_ = nullptr;
  }

  SolveReport solve(const SpringModel& model, SpringState& state, const SpringControls& controls,
                    const SolveBudget& budgetIn) override {
    Stopwatch clock(budgetIn);
    SolveReport report;
    if (!validInput(model, state, controls)) {
      report.status = SolveStatus::InvalidInput;
      return report;
    }
    SolveBudget budget = budgetIn;
    if (reference_) {
      budget.residualTolerance = budget.residualTolerance > 0.0
                                     ? std::min(budget.residualTolerance, kReferenceTolerance)
                                     : kReferenceTolerance;
      budget.maxIterations = std::max(budget.maxIterations, 1000);
    }
    const int n = model.nodeCount();
    const Points x0 = state.x;
    const Points v0 = state.v;
    const bool cacheValid = cacheMatches(model, state.x);
    applyControls(model, state, controls);
    terms_.invalidate(model.linkCount());
    energyKnown_ = false;
    Points& x = state.x;

    const std::vector<unsigned char> lastFree = std::move(free_);
    free_ = freeMask(model, controls);
    freeCount_ = static_cast<int>(std::count(free_.begin(), free_.end(), 1));
    scale_ = forceScale(model, controls);
    threshold_ = budget.residualTolerance * scale_;
    kMax_ = maxStiffness(model);
    indexSprings(n, controls.springs);
    if (static_cast<int>(local_.size()) != n) {
      local_.assign(static_cast<std::size_t>(n), -1);
      region_.clear();
    }

    // seeds of the active region: first the region of the last solve when the same
    // control nodes pull on the same topology (the pull will reach as far again)
    std::vector<int> seeds;
    const bool local = params_.activeRegion && !reference_;
    std::vector<int> movers = activeControlNodes(model, controls);
    clearRegion();
    if (local && sameTopology(model) && movers == lastMovers_) grow(model, lastRegion_, 0);
    if (local && cacheValid) {
      for (int c = 0; c < controls.size(); ++c) {
        const int node = controls.nodes[c];
        if (model.isFixed(node) || (lastX_.col(node) == controls.targets.col(c))) continue;
        for (int li : model.linksOf(node))
          if (model.link(li).alive && free_[model.otherEnd(li, node)])
            seeds.push_back(model.otherEnd(li, node));
      }
      if (!lastConverged_)
        for (int i : region_)
          if (free_[i]) seeds.push_back(i);
      // released control nodes
      if (lastFree.size() == free_.size())
        for (int i = 0; i < n; ++i)
          if (free_[i] && !lastFree[i]) seeds.push_back(i);
    } else if (local) {
      Points f;
      totalForces(model, x, f);
      for (int i = 0; i < n; ++i)
        if (free_[i] && f.col(i).norm() > threshold_) seeds.push_back(i);
    } else {
      for (int i = 0; i < n; ++i)
        if (free_[i]) seeds.push_back(i);
    }
    // the soft terms' nodes: their forces change with every set of terms
    for (const PointSpring& sp : controls.springs)
      for (int k = 0; k < sp.size(); ++k) seeds.push_back(sp.nodes[static_cast<std::size_t>(k)]);
    growths_ = 0;
    if (local) {
      // seeds already in the kept region bring no layers
      seeds.erase(std::remove_if(seeds.begin(), seeds.end(), [&](int i) { return local_[i] >= 0; }),
                  seeds.end());
    }
    grow(model, seeds, local ? 2 : 0);

    // newton iterations, on each part of the region alone where it falls into parts
    const SolveReport newton =
        local && static_cast<int>(region_.size()) == freeCount_ && freeCount_ < kMultigridNodes
            ? iterateByParts(model, x, budget, clock)
            : iterate(model, x, budget, clock, 0);
    report.status = newton.status;
    report.iterations = newton.iterations;
    report.residual = newton.residual;
    if (report.status == SolveStatus::Diverged) {
      state.x = x0;
      state.v = v0;
      report.seconds = clock.seconds();
      lastModel_ = nullptr;
      return report;
    }

    state.v.setZero();
    springs_ = nullptr;
    lastConverged_ = report.status == SolveStatus::Converged;
    lastRegion_ = region_;
    lastMovers_ = std::move(movers);
    remember(model, x);
    report.seconds = clock.seconds();
    return report;
  }

 private:
  /// Newton iterations on the region until it is in balance, with the kept factors kept_[slot]
  /// (0: the region's, 1 + c: part c's); Diverged leaves x where it went (the caller restores
  /// the state).
  SolveReport iterate(const SpringModel& model, Points& x, const SolveBudget& budget,
                      const Stopwatch& clock, std::size_t slot) {
    if (kept_.size() <= slot) kept_.resize(slot + 1);
    factors_ = &kept_[slot];
    SolveReport report;
    report.status = SolveStatus::IterationLimit;
    const bool local = params_.activeRegion && !reference_;
    double startResidual = -1.0;
    while (true) {
      bool grewThisStep = false;
      double residual = regionResidual(model, x);
      // grow while the boundary is out of balance
      while (local && !boundaryOut_.empty()) {
        grow(model, boundaryOut_, 1 << std::min(++growths_, 12));
        grewThisStep = true;
        residual = regionResidual(model, x);
      }
      report.residual = residual / scale_;
      if (startResidual < 0.0) startResidual = residual;
      if (!std::isfinite(residual) ||
          residual > kDivergenceFactor * std::max(startResidual, scale_)) {
        report.status = SolveStatus::Diverged;
        return report;
      }
      if (residual <= threshold_ || region_.empty()) {
        report.status = SolveStatus::Converged;
        return report;
      }
      if (report.iterations >= budget.maxIterations) return report;
      if (clock.expired()) {
        report.status = SolveStatus::TimeLimit;
        return report;
      }
      const bool moved = step(model, x, report.residual, grewThisStep);
      ++report.iterations;
      if (!moved) return report;
    }
  }

  /// iterate() on each part of the region (the file's essay, "Parts") in turn, the region
  /// being every free node: converged when every part is, its iterations and residual those
  /// of the part with the most.
  SolveReport iterateByParts(const SpringModel& model, Points& x, const SolveBudget& budget,
                             const Stopwatch& clock) {
    findParts(model);
    if (parts_.size() < 2) return iterate(model, x, budget, clock, 0);
    const std::vector<int> whole = region_;
    SolveReport total;
    total.status = SolveStatus::Converged;
    closed_ = true;
    for (std::size_t c = 0; c < parts_.size(); ++c) {
      setRegion(parts_[c]);
      const SolveReport part = iterate(model, x, budget, clock, c + 1);
      total.iterations = std::max(total.iterations, part.iterations);
      total.residual = std::max(total.residual, part.residual);
      if (part.status == SolveStatus::Converged) continue;
      if (total.status == SolveStatus::Converged || part.status == SolveStatus::Diverged)
        total.status = part.status;
      if (part.status == SolveStatus::Diverged) break;
    }
    closed_ = false;
    setRegion(whole);
    return total;
  }

  /// The region's parts into parts_ (region_parts.h), the links' sets kept while the topology
  /// and the region stay.
  void findParts(const SpringModel& model) {
    if (!(linkSetsModel_ == &model && linkSetsLinks_ == model.linkCount() &&
          linkSetsAlive_ == model.aliveLinkCount() && linkSetsRegion_ == region_)) {
      linkSets_ = linkSets(model, region_, local_);
      linkSetsModel_ = &model;
      linkSetsLinks_ = model.linkCount();
      linkSetsAlive_ = model.aliveLinkCount();
      linkSetsRegion_ = region_;
    }
    regionParts(linkSets_, *springs_, region_, local_, parts_);
  }

  /// The region becomes `nodes` (free ones, none repeated), in that order.
  void setRegion(const std::vector<int>& nodes) {
    clearRegion();
    for (int i : nodes) {
      local_[i] = static_cast<int>(region_.size());
      region_.push_back(i);
    }
  }

  bool sameTopology(const SpringModel& model) const {
    return lastModel_ == &model && lastNodes_ == model.nodeCount() &&
           lastLinks_ == model.linkCount() && lastAlive_ == model.aliveLinkCount();
  }

  bool cacheMatches(const SpringModel& model, const Points& x) const {
    return sameTopology(model) && lastGravity_ == model.gravity && lastX_.cols() == x.cols() &&
           std::memcmp(lastX_.data(), x.data(), sizeof(double) * x.size()) == 0;
  }

  void remember(const SpringModel& model, const Points& x) {
    lastModel_ = &model;
    lastNodes_ = model.nodeCount();
    lastLinks_ = model.linkCount();
    lastAlive_ = model.aliveLinkCount();
    lastGravity_ = model.gravity;
    lastX_ = x;
  }

  /// Per node, the soft terms that act on it (and its slot in each).
  void indexSprings(int n, const std::vector<PointSpring>& springs) {
    springs_ = &springs;
    springStart_.assign(static_cast<std::size_t>(n) + 1, 0);
    for (const PointSpring& sp : springs)
      for (int k = 0; k < sp.size(); ++k)
        ++springStart_[static_cast<std::size_t>(sp.nodes[static_cast<std::size_t>(k)]) + 1];
    for (int i = 0; i < n; ++i)
      springStart_[static_cast<std::size_t>(i) + 1] += springStart_[static_cast<std::size_t>(i)];
    springOf_.resize(static_cast<std::size_t>(springStart_.back()));
    std::vector<int> fill(springStart_.begin(), springStart_.end() - 1);
    for (int t = 0; t < static_cast<int>(springs.size()); ++t) {
      const PointSpring& sp = springs[static_cast<std::size_t>(t)];
      for (int k = 0; k < sp.size(); ++k)
        springOf_[static_cast<std::size_t>(
            fill[static_cast<std::size_t>(sp.nodes[static_cast<std::size_t>(k)])]++)] = {t, k};
    }
  }

  void clearRegion() {
    for (int i : region_) local_[i] = -1;
    region_.clear();
    energyKnown_ = false;
  }

  /// Adds `nodes` (free ones) to the region, then `layers` breadth-first layers of free nodes.
  void grow(const SpringModel& model, const std::vector<int>& nodes, int layers) {
    energyKnown_ = false;
    std::vector<int> frontier;
    for (int i : nodes)
      if (free_[i] && local_[i] < 0) {
        local_[i] = static_cast<int>(region_.size());
        region_.push_back(i);
        frontier.push_back(i);
      }
    std::vector<int> next;
    for (int layer = 0; layer < layers && !frontier.empty(); ++layer) {
      next.clear();
      for (int i : frontier)
        for (int li : model.linksOf(i)) {
          if (!model.link(li).alive) continue;
          const int j = model.otherEnd(li, i);
          if (!free_[j] || local_[j] >= 0) continue;
          local_[j] = static_cast<int>(region_.size());
          region_.push_back(j);
          next.push_back(j);
        }
      frontier.swap(next);
    }
    // a region over most of the mesh saves little: take all of it, once, so that it
    // (and its multigrid hierarchy) stays the same from cycle to cycle
    if (2 * static_cast<int>(region_.size()) > freeCount_ &&
        static_cast<int>(region_.size()) < freeCount_) {
      region_.clear();
      for (int i = 0; i < static_cast<int>(free_.size()); ++i)
        if (free_[i]) {
          local_[i] = static_cast<int>(region_.size());
          region_.push_back(i);
        }
    }
  }

  /// Total force on node i (µN).
  Vec3 nodeForce(const SpringModel& model, const Points& x, int i) const {
    Vec3 f = model.mass(i) * model.gravity;
    for (int li : model.linksOf(i)) {
      const Link& link = model.link(li);
      if (!link.alive) continue;
      const Vec3 fl = terms_.force(model, x, li);
      f += link.a == i ? fl : Vec3(-fl);
    }
    for (int e = springStart_[static_cast<std::size_t>(i)];
         e < springStart_[static_cast<std::size_t>(i) + 1]; ++e) {
      const auto [t, slot] = springOf_[static_cast<std::size_t>(e)];
      const PointSpring& sp = (*springs_)[static_cast<std::size_t>(t)];
      f += sp.weights[static_cast<std::size_t>(slot)] *
           pointSpringForce(sp, pointSpringOffset(sp, x));
    }
    return f;
  }

  /// Forces on the region (into force_), the boundary nodes out of balance (into
  /// boundaryOut_), and the largest |f| over both (µN).
  double regionResidual(const SpringModel& model, const Points& x) {
    const int m = static_cast<int>(region_.size());
    force_.resize(3 * m);
    double worst = 0.0;
    for (int r = 0; r < m; ++r) {
      const Vec3 f = nodeForce(model, x, region_[r]);
      force_.segment<3>(3 * r) = f;
      worst = std::max(worst, f.norm());
    }
    boundaryOut_.clear();
    if (closed_ || static_cast<int>(region_.size()) == freeCount_) return worst;
    seen_.clear();
    for (int i : region_)
      for (int li : model.linksOf(i)) {
        if (!model.link(li).alive) continue;
        const int j = model.otherEnd(li, i);
        if (!free_[j] || local_[j] >= 0) continue;
        seen_.push_back(j);
      }
    std::sort(seen_.begin(), seen_.end());
    seen_.erase(std::unique(seen_.begin(), seen_.end()), seen_.end());
    for (int j : seen_) {
      const double fj = nodeForce(model, x, j).norm();
      worst = std::max(worst, fj);
      if (fj > threshold_) boundaryOut_.push_back(j);
    }
    return worst;
  }

  /// Energy of every link touching the region plus the region's weight potential (nJ).
  double regionEnergy(const SpringModel& model, const Points& x) const {
    double e = 0.0;
    for (int i : region_) {
      for (int li : model.linksOf(i)) {
        const Link& link = model.link(li);
        if (!link.alive) continue;
        const int j = model.otherEnd(li, i);
        if (local_[j] >= 0 && j < i) continue;  // counted from j
        e += terms_.energy(model, x, li);
      }
      e -= model.mass(i) * model.gravity.dot(x.col(i));
    }
    for (const PointSpring& sp : *springs_)
      if (touchesRegion(sp)) e += pointSpringEnergy(sp, pointSpringOffset(sp, x));
    return e;
  }

  bool touchesRegion(const PointSpring& sp) const {
    for (int k = 0; k < sp.size(); ++k)
      if (local_[static_cast<std::size_t>(sp.nodes[static_cast<std::size_t>(k)])] >= 0) return true;
    return false;
  }

  /// The region's Hessian into system_: the links' true Hessians, or their PSD projections
  /// (`clamp`), plus the soft terms, plus a tiny diagonal shift.
  void assemble(const SpringModel& model, const Points& x, bool clamp) {
    const int m = static_cast<int>(region_.size());
    system_.clear(m);
    for (int r = 0; r < m; ++r) {
      const int i = region_[r];
      for (int li : model.linksOf(i)) {
        const Link& link = model.link(li);
        if (!link.alive) continue;
        const int j = model.otherEnd(li, i);
        const int s = local_[j];
        if (s >= 0 && j < i) continue;
        const Eigen::Matrix3d h = terms_.hessian(model, x, li, i, j, clamp);
        system_.diag[r] += h;
        if (s >= 0) {
          system_.diag[s] += h;
          system_.off.push_back({r, s, SymBlock::from(-h)});
        }
      }
      system_.diag[r] += 1e-9 * kMax_ * Eigen::Matrix3d::Identity();
    }
    for (const PointSpring& sp : *springs_) {
      const Eigen::Matrix3d h = pointSpringHessian(sp, pointSpringOffset(sp, x));
      if (h.isZero(0.0)) continue;
      for (int a = 0; a < sp.size(); ++a) {
        const int ra = local_[static_cast<std::size_t>(sp.nodes[static_cast<std::size_t>(a)])];
        if (ra < 0) continue;
        const double ca = sp.weights[static_cast<std::size_t>(a)];
        system_.diag[ra] += ca * ca * h;
        for (int b = a + 1; b < sp.size(); ++b) {
          const int rb = local_[static_cast<std::size_t>(sp.nodes[static_cast<std::size_t>(b)])];
          if (rb >= 0)
            system_.off.push_back(
                {ra, rb, SymBlock::from(ca * sp.weights[static_cast<std::size_t>(b)] * h)});
        }
      }
    }
  }

  /// The newton direction on a small region: CG preconditioned by the kept factorisation
  /// while it serves, else the true Hessian factorised, else its projection.
  bool directDirection(const SpringModel& model, const Points& x, double eta) {
    assemble(model, x, false);
    KeptFactors& kept = *factors_;
    if (kept.valid && kept.region == region_ && kept.alive == model.aliveLinkCount() &&
        kept.lastPcgIterations <= kStaleIterations) {
      const PcgResult pcg = solvePcg(system_, FactorPreconditioner(kept.cholesky), force_,
                                     direction_, eta, kRefactorIterations);
      kept.lastPcgIterations = pcg.iterations;
      if (pcg.ok && pcg.relativeResidual <= eta && direction_.allFinite()) return true;
    }
    kept.lastPcgIterations = 0;
    kept.valid = false;
    if (!factorise()) {
      // indefinite (compressed links): this iteration takes the projection. (Keeping the
      // projection for the rest of the solve converges linearly: 20+ iterations where the
      // true Hessian, tried again next iteration, needs 13 on the stitch's worst step.)
      assemble(model, x, true);
      if (!factorise()) return false;
    }
    kept.valid = true;
    kept.region = region_;
    kept.alive = model.aliveLinkCount();
    kept.cholesky.solve(force_, direction_);
    return direction_.allFinite();
  }

  /// Factorises system_ by sparse Cholesky (supernodal_cholesky.h); false when it is not
  /// positive definite. The ordering and symbolic analysis are kept while the pattern stays.
  bool factorise() { return factors_->cholesky.factorize(system_); }

  /// One Newton step on the region from force_ (current); false when it could not move.
  /// `growing`: the region grew just before this step.
  bool step(const SpringModel& model, Points& x, double relativeResidual, bool growing) {
    const int m = static_cast<int>(region_.size());
    // the newton direction: on small regions exact, from the true Hessian while it is
    // positive definite (quadratic convergence) and its projection where it is not; on
    // large ones inexact, by PCG on the true Hessian preconditioned by a multigrid
    // hierarchy of the projection (CG stops at a direction of negative curvature and keeps
    // what it has: truncated Newton). CG on the projection alone converged linearly,
    // halving the residual per iteration once compressed links and the thread's pull
    // entered: 10 Newton iterations a step where the true Hessian takes 4.
    double eta = params_.linearTolerance;
    if (!(eta > 0.0)) eta = reference_ ? 1e-8 : std::clamp(relativeResidual, 1e-4, 1e-2);
    PcgResult pcg;
    bool direct = false;
    bool projected = true;
    if (m < kMultigridNodes) direct = directDirection(model, x, eta);
    Hierarchy* kept = m >= kMultigridNodes ? fittingHierarchy(model) : nullptr;
    if (direct) {
      // done above
    } else if (m >= kMultigridNodes && (!growing || m == freeCount_ || kept)) {
      // multigrid-preconditioned CG, the hierarchy kept while it serves (and not built
      // for a region that may still grow); it is built on the projection, which is
      // positive definite
      if (!kept) {
        assemble(model, x, true);
        kept = &buildMultigrid(model, x);
      }
      kept->lastUse = ++uses_;
      assemble(model, x, false);
      projected = false;
      pcg = solvePcg(system_, kept->multigrid, force_, direction_, eta, 300);
      if (!pcg.ok) {
        // negative curvature on the first direction: the projection's Newton direction
        assemble(model, x, true);
        projected = true;
        pcg = solvePcg(system_, kept->multigrid, force_, direction_, eta, 300);
      }
      if (pcg.iterations > kRebuildIterations || !pcg.ok) kept->region.clear();
    } else {
      if (m >= kMultigridNodes) assemble(model, x, true);
      pcg = solvePcg(system_, force_, direction_, eta, std::max(50, 3 * m));
    }
    double slope = force_.dot(direction_);
    if (!pcg.ok || !(slope > 0.0) || !direction_.allFinite()) {
      if (!projected) assemble(model, x, true);
      // fall back to the block-Jacobi scaled force
      for (int r = 0; r < m; ++r)
        direction_.segment<3>(3 * r) = invertBlock(system_.diag[r]) * force_.segment<3>(3 * r);
      slope = force_.dot(direction_);
      if (!(slope > 0.0)) return false;
    }

    // backtracking line search on the energy (Armijo), accepting a full step that lowers
    // |f| when the energy change is below rounding; the energy at the start is the one the
    // last search ended on, while the region stays
    const double e0 = energyKnown_ ? knownEnergy_ : regionEnergy(model, x);
    const double f0 = force_.squaredNorm();
    start_.resize(3, m);
    for (int r = 0; r < m; ++r) start_.col(r) = x.col(region_[r]);
    double t = 1.0;
    energyKnown_ = true;
    for (int attempt = 0; attempt < 30; ++attempt, t *= 0.5) {
      for (int r = 0; r < m; ++r)
        x.col(region_[r]) = start_.col(r) + t * direction_.segment<3>(3 * r);
      terms_.invalidate(model.linkCount());
      knownEnergy_ = regionEnergy(model, x);
      if (knownEnergy_ <= e0 - 1e-4 * t * slope) return true;
      if (std::abs(knownEnergy_ - e0) <= 1e-12 * (std::abs(e0) + 1.0)) {
        double f = 0.0;
        for (int r = 0; r < m; ++r) f += nodeForce(model, x, region_[r]).squaredNorm();
        if (f < f0) return true;
      }
    }
    for (int r = 0; r < m; ++r) x.col(region_[r]) = start_.col(r);
    terms_.invalidate(model.linkCount());
    knownEnergy_ = e0;
    return false;
  }

  /// The kept hierarchy built for this model, topology and region, or null.
  Hierarchy* fittingHierarchy(const SpringModel& model) {
    for (Hierarchy& h : hierarchies_)
      if (h.model == &model && h.links == model.linkCount() && h.alive == model.aliveLinkCount() &&
          h.region == region_)
        return &h;
    return nullptr;
  }

  /// Builds a hierarchy for the region in place of the least recently used one.
  Hierarchy& buildMultigrid(const SpringModel& model, const Points& x) {
    Hierarchy& h =
        hierarchies_[0].lastUse <= hierarchies_[1].lastUse ? hierarchies_[0] : hierarchies_[1];
    const int m = static_cast<int>(region_.size());
    Eigen::Matrix3Xd positions(3, m);
    for (int r = 0; r < m; ++r) positions.col(r) = x.col(region_[r]);
    h.multigrid.build(system_, positions);
    h.model = &model;
    h.links = model.linkCount();
    h.alive = model.aliveLinkCount();
    h.region = region_;
    return h;
  }

  SolverParams params_;
  bool reference_;
  // the last state returned, to find what moved since
  const SpringModel* lastModel_ = nullptr;
  int lastNodes_ = -1, lastLinks_ = -1, lastAlive_ = -1;
  Points lastX_{3, 0};
  Vec3 lastGravity_ = Vec3::Zero();
  bool lastConverged_ = true;
  std::vector<int> lastRegion_;  ///< the region of the last solve
  std::vector<int> lastMovers_;  ///< the control nodes that pulled in it
  // per solve
  std::vector<unsigned char> free_;
  int freeCount_ = 0;
  double scale_ = 1.0, threshold_ = 0.0, kMax_ = 0.0;
  std::vector<int> local_;   ///< per node: index in region_, or −1
  std::vector<int> region_;  ///< the unknown nodes
  std::vector<int> boundaryOut_, seen_;
  int growths_ = 0;
  Eigen::VectorXd force_, direction_;
  mutable LinkTerms terms_;  ///< the links' spring terms at x, until a node moves
  Points start_;
  // regionEnergy at x as the last line search left it, until x or the region changes
  bool energyKnown_ = false;
  double knownEnergy_ = 0.0;
  BlockSystem system_;
  // the direct path: the kept factors of the region, or of each of its parts, and those of
  // the region (or part) iterated on
  std::vector<KeptFactors> kept_;
  KeptFactors* factors_ = nullptr;
  // the region's parts (node lists), the sets its links alone make (per region index its
  // root) and what they were made for, and whether the region is a part (closed: no free node
  // outside it is linked to it)
  std::vector<std::vector<int>> parts_;
  std::vector<int> linkSets_;
  const SpringModel* linkSetsModel_ = nullptr;
  int linkSetsLinks_ = -1, linkSetsAlive_ = -1;
  std::vector<int> linkSetsRegion_;
  bool closed_ = false;
  // the soft terms of this solve, and per node the (term, slot) pairs that act on it
  const std::vector<PointSpring>* springs_ = nullptr;
  std::vector<int> springStart_{0};
  std::vector<std::pair<int, int>> springOf_;
  // the multigrid hierarchies of the last two regions and what they were built for
  std::array<Hierarchy, 2> hierarchies_;
  long uses_ = 0;
};

}  // namespace

std::unique_ptr<TissueSolver> makeNewtonSolver(const SolverParams& params, bool reference) {
  return std::make_unique<NewtonSolver>(params, reference);
}

}  // namespace microsim::sim::detail
