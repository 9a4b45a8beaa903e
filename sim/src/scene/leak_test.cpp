#include "microsim/sim/scene/leak_test.h"

#include "microsim/sim/collide/end_gap.h"
#include "microsim/sim/scene/circumference_frame.h"
#include "microsim/sim/scene/scene.h"
#include "microsim/sim/solve/spring_kernels.h"
#include "solve/block_system.h"
#include "solve/supernodal_cholesky.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace microsim::sim {

namespace {

/// mmHg → g/(mm·s²) (= Pa): 1 mmHg = 133.322 Pa.
constexpr double kPascalPerMmHg = 133.322;
/// Armijo's sufficient decrease, the halvings a line search may take and the doublings it may
/// try after a shifted direction (see minimiseLeakProblem).
constexpr double kLeakArmijo = 1e-4;
constexpr int kLeakHalvings = 30;
constexpr int kLeakDoublings = 10;
/// The shift μ·I added to an indefinite Hessian: first this fraction of the stiffest link's
/// stiffness, then four times more until it factorises, and no more than the last. (The
/// shipped stitch's buckling end: 1e-8 to 1e-3 take 29–33 iterations, fourfold or tenfold;
/// 1e-2 up to 48, too stiff a start crawls out of the unstable shape.)
constexpr double kLeakFirstShift = 1e-5;
constexpr double kLeakLastShift = 1e4;

/// The angle frame of the suture line: end 0's axis, 0° toward `params.angleZero` or the camera.
CircumferenceFrame leakFrame(const SceneDef& def, const SceneVessel& end0,
                             const LeakTestParams& params) {
  const Vec3 axis = end0.def.direction.normalized();
  const Vec3 cutCentre = end0.def.origin + end0.def.length * axis;
  return circumferenceFrame(
      axis, params.angleZero ? *params.angleZero : Vec3(def.camera.eye - cutCentre));
}

/// A tie as a weighted point of six nodes: d = Σ w_k x_k = p_b − p_a.
struct LeakTieTerm {
  std::array<int, 6> nodes{};
  std::array<double, 6> weights{};
  double length = 0.0;  ///< mm
  double k = 0.0;       ///< g/s²
};

/// The tie's pull on d (µN, −∂E/∂d) and its Hessian in d (g/s²): E = ½ k (|d| − L)₊².
Vec3 leakTieForce(const LeakTieTerm& t, const Vec3& d) {
  const double l = d.norm();
  if (l <= t.length || l < kMinLength) return t.length > 0.0 ? Vec3::Zero() : Vec3(-t.k * d);
  return -t.k * (l - t.length) / l * d;
}

double leakTieEnergy(const LeakTieTerm& t, const Vec3& d) {
  const double over = std::max(d.norm() - t.length, 0.0);
  return 0.5 * t.k * over * over;
}

Eigen::Matrix3d leakTieHessian(const LeakTieTerm& t, const Vec3& d) {
  const double l = d.norm();
  if (l < kMinLength)
    return t.length > 0.0 ? Eigen::Matrix3d::Zero()
                          : Eigen::Matrix3d(t.k * Eigen::Matrix3d::Identity());
  if (l <= t.length) return Eigen::Matrix3d::Zero();
  const Vec3 u = d / l;
  const double s = (l - t.length) / l;
  return t.k * ((1.0 - s) * (u * u.transpose()) + s * Eigen::Matrix3d::Identity());
}

/// The potential Π of the header over the two ends' free nodes: the tissue's links, the ties
/// and the dead loads, with its forces and Hessian.
class LeakProblem {
 public:
  LeakProblem(const SpringModel& model, const std::array<const SceneVessel*, 2>& ends)
      : local_(static_cast<std::size_t>(model.nodeCount()), -1),
        load_(Points::Zero(3, model.nodeCount())) {
    for (const SceneVessel* v : ends) {
      const int count = 2 * v->def.rings * v->def.nodesPerRing;
      for (int i = v->firstNode; i < v->firstNode + count; ++i)
        if (!model.isFixed(i) && local_[static_cast<std::size_t>(i)] < 0) {
          local_[static_cast<std::size_t>(i)] = static_cast<int>(unknowns_.size());
          unknowns_.push_back(i);
        }
    }
    for (int i : unknowns_) load_.col(i) = model.mass(i) * model.gravity;
    for (const Link& l : model.links())
      if (l.alive && (isUnknown(l.a) || isUnknown(l.b))) links_.push_back(&l);
  }

  void addLoad(int node, const Vec3& f) { load_.col(node) += f; }
  void addTie(const LeakTieTerm& t) { ties_.push_back(t); }
  int size() const { return static_cast<int>(unknowns_.size()); }
  const std::vector<int>& unknowns() const { return unknowns_; }

  /// max over unknowns of |F_i|, or k_max · ℓ̄ when larger (µN).
  double forceScale() const {
    double kMax = 0.0, restSum = 0.0;
    for (const Link* l : links_) {
      kMax = std::max(kMax, l->k);
      restSum += l->rest;
    }
    double scale = links_.empty() ? 0.0 : kMax * restSum / static_cast<double>(links_.size());
    for (int i : unknowns_) scale = std::max(scale, load_.col(i).norm());
    return scale > 0.0 ? scale : 1.0;
  }

  double energy(const Points& x) const {
    double e = 0.0;
    for (const Link* l : links_) e += linkEnergy(*l, x.col(l->a), x.col(l->b));
    for (const LeakTieTerm& t : ties_) e += leakTieEnergy(t, tieOffset(t, x));
    for (int i : unknowns_) e -= load_.col(i).dot(x.col(i));
    return e;
  }

  /// −∇Π on the unknowns (3 · size(), µN).
  void forces(const Points& x, Eigen::VectorXd& f) const {
    f.setZero(3 * size());
    for (int i : unknowns_) f.segment<3>(3 * local(i)) = load_.col(i);
    for (const Link* l : links_) {
      const Vec3 fl = linkForce(*l, x.col(l->a), x.col(l->b));
      if (isUnknown(l->a)) f.segment<3>(3 * local(l->a)) += fl;
      if (isUnknown(l->b)) f.segment<3>(3 * local(l->b)) -= fl;
    }
    for (const LeakTieTerm& t : ties_) {
      const Vec3 ft = leakTieForce(t, tieOffset(t, x));
      for (std::size_t k = 0; k < t.nodes.size(); ++k)
        if (isUnknown(t.nodes[k])) f.segment<3>(3 * local(t.nodes[k])) += t.weights[k] * ft;
    }
  }

  /// The stiffest link's base stiffness (g/s²).
  double stiffest() const {
    double kMax = 0.0;
    for (const Link* l : links_) kMax = std::max(kMax, l->k);
    return kMax;
  }

  /// ∇²Π on the unknowns: the links' and the ties' Hessians, and the newton solver's tiny
  /// diagonal shift. The pattern is the same every call.
  void hessian(const Points& x, detail::BlockSystem& h) const {
    h.clear(size());
    for (const Link* l : links_) {
      const Eigen::Matrix3d hl = linkHessian(*l, x.col(l->a), x.col(l->b));
      const int a = local(l->a), b = local(l->b);
      if (a >= 0) h.diag[static_cast<std::size_t>(a)] += hl;
      if (b >= 0) h.diag[static_cast<std::size_t>(b)] += hl;
      if (a >= 0 && b >= 0) h.off.push_back({a, b, detail::SymBlock::from(-hl)});
    }
    for (const LeakTieTerm& t : ties_) {
      const Eigen::Matrix3d ht = leakTieHessian(t, tieOffset(t, x));
      for (std::size_t p = 0; p < t.nodes.size(); ++p) {
        const int a = local(t.nodes[p]);
        if (a < 0) continue;
        h.diag[static_cast<std::size_t>(a)] += t.weights[p] * t.weights[p] * ht;
        for (std::size_t q = p + 1; q < t.nodes.size(); ++q) {
          const int b = local(t.nodes[q]);
          if (b >= 0)
            h.off.push_back({a, b, detail::SymBlock::from(t.weights[p] * t.weights[q] * ht)});
        }
      }
    }
    const double shift = 1e-9 * stiffest();
    for (Eigen::Matrix3d& d : h.diag) d += shift * Eigen::Matrix3d::Identity();
  }

 private:
  bool isUnknown(int i) const { return local_[static_cast<std::size_t>(i)] >= 0; }
  int local(int i) const { return local_[static_cast<std::size_t>(i)]; }
  static Vec3 tieOffset(const LeakTieTerm& t, const Points& x) {
    Vec3 d = Vec3::Zero();
    for (std::size_t k = 0; k < t.nodes.size(); ++k) d += t.weights[k] * x.col(t.nodes[k]);
    return d;
  }

  std::vector<int> local_;  ///< per node: index among the unknowns, or −1
  std::vector<int> unknowns_;
  std::vector<const Link*> links_;  ///< alive links with an unknown end
  std::vector<LeakTieTerm> ties_;
  Points load_;  ///< dead loads, 3 by #N (µN)
};

/// The pressure's dead loads on `end` (header): its inner wall, shared by the two hulls, and
/// the end-cap thrust on its cut face away from the other end.
void addLumenLoads(LeakProblem& problem, const SpringModel& model, const SceneVessel& end,
                   double pressure) {
  const auto rest = model.restPositions();
  const auto areaNormal = [&](int face) {
    const auto& t = model.triangles()[static_cast<std::size_t>(face)];
    return Vec3(0.5 * (rest.col(t[1]) - rest.col(t[0])).cross(rest.col(t[2]) - rest.col(t[0])));
  };
  // the inner wall: inner faces' normals point into the lumen, the pressure pushes out; half
  // on each corner's node, half on its outer twin (the same ring and sector, P nodes on)
  for (int face = end.innerSurface.begin; face < end.innerSurface.end; ++face) {
    const Vec3 corner = -pressure * areaNormal(face) / 3.0;
    for (int k : model.triangles()[static_cast<std::size_t>(face)]) {
      problem.addLoad(k, 0.5 * corner);
      problem.addLoad(k + end.def.nodesPerRing, 0.5 * corner);
    }
  }
  // the end cap: p·π·r_i² on the cut face by area, along −axis (the other end is ahead)
  double area = 0.0;
  for (int face = end.cutEnd.begin; face < end.cutEnd.end; ++face) area += areaNormal(face).norm();
  if (!(area > 0.0)) return;
  const double lumen = end.def.radius - end.def.wallThickness;
  const double thrust = pressure * std::numbers::pi * lumen * lumen;
  const Vec3 away = -end.def.direction.normalized();
  for (int face = end.cutEnd.begin; face < end.cutEnd.end; ++face) {
    const Vec3 corner = thrust * areaNormal(face).norm() / (3.0 * area) * away;
    for (int k : model.triangles()[static_cast<std::size_t>(face)]) problem.addLoad(k, corner);
  }
}

/// Backtracking (Armijo) from step length t = 1 along a direction of slope −∇Π·δ = `slope` > 0
/// from Π = e0; a step whose change of Π is below rounding is taken when it lowers |∇Π|
/// (`f` the forces at the start, `trial` scratch). `moveTo(t)` places x and returns Π there.
/// False when no step length lowers either.
template <class MoveTo>
bool backtrack(const LeakProblem& problem, const MoveTo& moveTo, const Points& x, double e0,
               double slope, const Eigen::VectorXd& f, Eigen::VectorXd& trial, double& t) {
  for (int halving = 0; halving < kLeakHalvings; ++halving, t *= 0.5) {
    const double e = moveTo(t);
    if (e <= e0 - kLeakArmijo * t * slope) return true;
    if (std::abs(e - e0) <= 1e-12 * (std::abs(e0) + 1.0)) {
      problem.forces(x, trial);
      if (trial.squaredNorm() < f.squaredNorm()) return true;
    }
  }
  return false;
}

/// Newton with a backtracking line search on Π from x (moved in place), as the header says.
LeakTestStatus minimiseLeakProblem(const LeakProblem& problem, Points& x,
                                   const LeakTestParams& params, LeakResult& r) {
  const std::vector<int>& unknowns = problem.unknowns();
  const int m = problem.size();
  const double scale = problem.forceScale();
  detail::BlockSystem h;
  detail::SupernodalCholesky cholesky;
  Eigen::VectorXd f, step, trial;
  Points start(3, m);
  for (r.iterations = 0;; ++r.iterations) {
    problem.forces(x, f);
    double worst = 0.0;
    for (int i = 0; i < m; ++i) worst = std::max(worst, f.segment<3>(3 * i).norm());
    r.residual = worst / scale;
    if (!std::isfinite(r.residual)) return LeakTestStatus::SolverFailed;
    if (r.residual <= params.tolerance) return LeakTestStatus::Solved;
    if (r.iterations >= params.maxIterations) return LeakTestStatus::NotConverged;

    // the direction: the true Hessian, shifted where compressed links make it indefinite
    problem.hessian(x, h);
    double shift = 0.0;
    while (!cholesky.factorize(h)) {
      const double add = shift == 0.0 ? kLeakFirstShift * problem.stiffest() : 3.0 * shift;
      for (Eigen::Matrix3d& d : h.diag) d += add * Eigen::Matrix3d::Identity();
      shift += add;
      if (shift > kLeakLastShift * problem.stiffest()) return LeakTestStatus::SolverFailed;
    }
    cholesky.solve(f, step);
    const double slope = f.dot(step);
    if (!step.allFinite() || !(slope > 0.0)) return LeakTestStatus::SolverFailed;

    // the step along it
    const double e0 = problem.energy(x);
    for (int i = 0; i < m; ++i) start.col(i) = x.col(unknowns[static_cast<std::size_t>(i)]);
    const auto moveTo = [&](double t) {
      for (int i = 0; i < m; ++i)
        x.col(unknowns[static_cast<std::size_t>(i)]) = start.col(i) + t * step.segment<3>(3 * i);
      return problem.energy(x);
    };
    double t = 1.0;
    if (!backtrack(problem, moveTo, x, e0, slope, f, trial, t)) {
      moveTo(0.0);
      return LeakTestStatus::SolverFailed;
    }
    // a shifted direction is short along the way out of an unstable shape: longer steps
    // while Π keeps falling as Armijo asks
    if (shift > 0.0 && t == 1.0) {
      double e = problem.energy(x);
      for (int doubling = 0; doubling < kLeakDoublings; ++doubling) {
        const double longer = moveTo(2.0 * t);
        if (!(longer <= e0 - kLeakArmijo * 2.0 * t * slope) || !(longer < e)) {
          moveTo(t);
          break;
        }
        t *= 2.0;
        e = longer;
      }
    }
  }
}

}  // namespace

std::vector<SutureLineSample> sutureLine(const SceneDef& def, const Points& x,
                                         const LeakTestParams& params) {
  const auto ends = collide::severedEnds(def.vessels);
  if (ends[0] == nullptr || ends[1] == nullptr || !(params.sampleDeg > 0.0)) return {};
  const CircumferenceFrame frame = leakFrame(def, *ends[0], params);
  const SpringModel& model = def.tissue.model;

  // at each angle the axial opening of the narrower hull, closed at 0
  const int samples = std::max(1, static_cast<int>(std::lround(360.0 / params.sampleDeg)));
  std::vector<SutureLineSample> line;
  line.reserve(static_cast<std::size_t>(samples));
  for (int s = 0; s < samples; ++s) {
    const double deg = 360.0 * s / samples;
    const Vec3 d = frame.direction(deg);
    double gap = std::numeric_limits<double>::infinity();
    for (VesselHull hull : {VesselHull::Outer, VesselHull::Inner}) {
      const Vec3 lip0 = collide::cutRingLip(model, x, *ends[0], d, hull);
      const Vec3 lip1 = collide::cutRingLip(model, x, *ends[1], d, hull);
      gap = std::min(gap, (lip1 - lip0).dot(frame.axis));
    }
    line.push_back({deg, std::max(gap, 0.0)});
  }
  return line;
}

LeakResult leakTest(const SceneDef& def, const Points& x, const std::vector<LeakTie>& ties,
                    const LeakTestParams& params) {
  LeakResult r;
  r.pressureMmHg = params.pressureMmHg;
  r.x = x;
  const auto ends = collide::severedEnds(def.vessels);
  if (ends[0] == nullptr || ends[1] == nullptr) {
    r.status = LeakTestStatus::NoSeveredVessel;
    return r;
  }
  r.thresholdMm = params.leakGapWalls * ends[0]->def.wallThickness;
  if (ties.empty()) {
    r.status = LeakTestStatus::NoStitches;
    return r;
  }
  const SpringModel& model = def.tissue.model;
  const int faces = static_cast<int>(model.triangles().size());
  const auto onTissue = [faces](const TissuePoint& p) { return p.face >= 0 && p.face < faces; };
  for (const LeakTie& t : ties)
    if (!onTissue(t.a) || !onTissue(t.b) || !(t.length >= 0.0)) {
      r.status = LeakTestStatus::BadTie;
      return r;
    }

  // the potential: the two ends' links, the ties, the pressure's dead loads
  LeakProblem problem(model, ends);
  const double pressure = params.pressureMmHg * kPascalPerMmHg;
  for (const SceneVessel* end : ends) addLumenLoads(problem, model, *end, pressure);
  for (const LeakTie& t : ties) {
    LeakTieTerm term;
    const auto& fa = model.triangles()[static_cast<std::size_t>(t.a.face)];
    const auto& fb = model.triangles()[static_cast<std::size_t>(t.b.face)];
    for (std::size_t k = 0; k < 3; ++k) {
      term.nodes[k] = fa[k];
      term.weights[k] = -t.a.barycentric[static_cast<Eigen::Index>(k)];
      term.nodes[k + 3] = fb[k];
      term.weights[k + 3] = t.b.barycentric[static_cast<Eigen::Index>(k)];
    }
    term.length = t.length;
    term.k = params.threadRigidity / std::max(t.length, ends[0]->def.wallThickness);
    problem.addTie(term);
  }

  // the minimum, then the suture line there
  r.status = minimiseLeakProblem(problem, r.x, params, r);
  if (r.status != LeakTestStatus::Solved) return r;
  r.line = sutureLine(def, r.x, params);
  const auto widest = std::max_element(
      r.line.begin(), r.line.end(), [](const auto& a, const auto& b) { return a.gapMm < b.gapMm; });
  if (widest == r.line.end()) return r;
  r.largestGapMm = widest->gapMm;
  r.angleDeg = widest->angleDeg;
  r.leak = r.largestGapMm > r.thresholdMm;
  return r;
}

std::vector<LeakTie> sutureTies(const Scene& scene) {
  const suture::SutureState* state = scene.sutureState();
  if (state == nullptr) return {};
  const auto& vessels = scene.def().vessels;
  const auto endOf = [&](int face) {
    const auto on = vesselSurfaceOf(vessels, face);
    return on ? vessels[static_cast<std::size_t>(on->first)].end : -1;
  };

  // neighbours along the thread through different ends, with unbroken thread between them
  std::vector<LeakTie> ties;
  for (std::size_t i = 0; i + 1 < state->pierces.size(); ++i) {
    const suture::Pierce& p = state->pierces[i];
    const suture::Pierce& q = state->pierces[i + 1];
    const int endP = endOf(p.face);
    const int endQ = endOf(q.face);
    if (endP < 0 || endQ < 0 || endP == endQ) continue;
    const int lo = std::min(p.node, q.node);
    const int hi = std::max(p.node, q.node);
    double length = 0.0;
    bool whole = true;
    for (int l = lo; l < hi; ++l) {
      whole = whole && state->alive[static_cast<std::size_t>(l)] != 0;
      length += (state->x.col(l + 1) - state->x.col(l)).norm();
    }
    if (whole) ties.push_back({{p.face, p.barycentric}, {q.face, q.barycentric}, length});
  }
  return ties;
}

LeakResult leakTest(const Scene& scene, const LeakTestParams& params) {
  return leakTest(scene.def(), scene.tissueState().x, sutureTies(scene), params);
}

}  // namespace microsim::sim
