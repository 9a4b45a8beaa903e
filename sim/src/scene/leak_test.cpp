#include "microsim/sim/scene/leak_test.h"

#include "microsim/sim/collide/end_gap.h"
#include "microsim/sim/collide/tissue_contact.h"
#include "microsim/sim/scene/scene.h"
#include "microsim/sim/solve/solver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>

namespace microsim::sim {

namespace {

/// mmHg → g/(mm·s²) (= Pa): 1 mmHg = 133.322 Pa.
constexpr double kPascalPerMmHg = 133.322;
/// The pressure springs' stiffness as a fraction of the mean link's: soft enough that a round
/// moves the wall nearly all the way to the next one's equilibrium (header: the rounds).
constexpr double kPressureSpringShare = 1e-3;
/// Newton iterations and relative residual of one round's solve.
constexpr int kLeakSolveIterations = 100;
constexpr double kLeakSolveTolerance = 1e-9;
/// Solves a round may take when they keep running into faces.
constexpr int kLeakContactSolves = 4;

/// A face point at positions x.
Vec3 leakPointAt(const SpringModel& model, const Points& x, const TissuePoint& p) {
  const auto& t = model.triangles()[static_cast<std::size_t>(p.face)];
  return p.barycentric.x() * x.col(t[0]) + p.barycentric.y() * x.col(t[1]) +
         p.barycentric.z() * x.col(t[2]);
}

/// The angle frame of the suture line: end 0's axis and the unit 0° direction normal to it.
struct LeakFrame {
  Vec3 axis = Vec3::UnitX();
  Vec3 zero = Vec3::UnitZ();

  Vec3 direction(double deg) const {
    const double a = deg * std::numbers::pi / 180.0;
    return std::cos(a) * zero + std::sin(a) * axis.cross(zero);
  }
};

LeakFrame leakFrame(const SceneDef& def, const SceneVessel& end0, const LeakTestParams& params) {
  LeakFrame f;
  f.axis = end0.def.direction.normalized();
  const Vec3 cutCentre = end0.def.origin + end0.def.length * f.axis;
  Vec3 toward = params.angleZero ? *params.angleZero : Vec3(def.camera.eye - cutCentre);
  toward -= toward.dot(f.axis) * f.axis;
  f.zero = toward.norm() > 1e-12 ? Vec3(toward.normalized()) : Vec3(f.axis.unitOrthogonal());
  return f;
}

/// The pressure on the inner faces of `ends` at x, per node (3 by #N, µN).
Points lumenPressureForces(const SpringModel& model, const Points& x,
                           const std::array<const SceneVessel*, 2>& ends, double pressure) {
  Points f = Points::Zero(3, x.cols());
  for (const SceneVessel* v : ends)
    for (int face = v->innerSurface.begin; face < v->innerSurface.end; ++face) {
      const auto& t = model.triangles()[static_cast<std::size_t>(face)];
      // the face normal points into the lumen: the pressure pushes the other way
      const Vec3 areaNormal = 0.5 * (x.col(t[1]) - x.col(t[0])).cross(x.col(t[2]) - x.col(t[0]));
      const Vec3 corner = -pressure * areaNormal / 3.0;
      for (int k : t) f.col(k) += corner;
    }
  return f;
}

/// Half a tie: a zero-rest spring from knot node `knot` to face point p, anchored half the tie's
/// length along its direction: E = ½k|sign·(x_knot − p) − anchor|².
PointSpring leakTieHalf(const SpringModel& model, int knot, const TissuePoint& p, double sign,
                        const Vec3& anchor, double k) {
  const auto& t = model.triangles()[static_cast<std::size_t>(p.face)];
  PointSpring s;
  s.nodes = {knot, t[0], t[1], t[2]};
  s.weights = {sign, -sign * p.barycentric.x(), -sign * p.barycentric.y(),
               -sign * p.barycentric.z()};
  s.anchor = anchor;
  s.k = k;
  return s;
}

double meanLinkStiffness(const SpringModel& model) {
  double sum = 0.0;
  int count = 0;
  for (const Link& l : model.links())
    if (l.alive) {
      sum += l.k;
      ++count;
    }
  return count > 0 ? sum / count : 1.0;
}

}  // namespace

std::vector<SutureLineSample> sutureLine(const SceneDef& def, const Points& x,
                                         const LeakTestParams& params) {
  const auto ends = collide::severedEnds(def.vessels);
  if (ends[0] == nullptr || ends[1] == nullptr || !(params.sampleDeg > 0.0)) return {};
  const LeakFrame frame = leakFrame(def, *ends[0], params);
  const SpringModel& model = def.tissue.model;

  // at each angle the narrower of the outer and the inner opening
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
      gap = std::min(gap, (lip1 - lip0).norm());
    }
    line.push_back({deg, gap});
  }
  return line;
}

std::optional<LeakResult> leakTest(const SceneDef& def, const Points& x,
                                   const std::vector<LeakTie>& ties, const LeakTestParams& params) {
  const auto ends = collide::severedEnds(def.vessels);
  if (ends[0] == nullptr || ends[1] == nullptr || !(params.sampleDeg > 0.0)) return std::nullopt;
  const int faces = static_cast<int>(def.tissue.model.triangles().size());
  for (const LeakTie& t : ties)
    if (t.a.face < 0 || t.a.face >= faces || t.b.face < 0 || t.b.face >= faces) return std::nullopt;

  // the tissue with a knot node per tie, placed between its two points
  SpringModel model = def.tissue.model;
  const int n = model.nodeCount();
  for (const LeakTie& t : ties)
    model.addNode(0.5 * (leakPointAt(model, x, t.a) + leakPointAt(model, x, t.b)), 1.0, 0.0);
  model.finalize();
  SpringState state;
  state.x.resize(3, model.nodeCount());
  state.x.leftCols(n) = x;
  for (std::size_t i = 0; i < ties.size(); ++i)
    state.x.col(n + static_cast<int>(i)) = model.restPositions().col(n + static_cast<int>(i));
  state.v = Points::Zero(3, model.nodeCount());

  collide::TissueContact contact(model, def.contact.params);
  const double tieK = params.tieStiffness > 0.0 ? params.tieStiffness : contact.stiffness();
  const double kp = kPressureSpringShare * meanLinkStiffness(model);
  const double pressure = params.pressureMmHg * kPascalPerMmHg;
  SolverParams solverParams = def.solver.params;
  solverParams.activeRegion = false;
  const std::unique_ptr<TissueSolver> solver = makeSolver("newton", solverParams);
  SolveBudget budget;
  budget.maxIterations = kLeakSolveIterations;
  budget.residualTolerance = kLeakSolveTolerance;

  LeakResult r;
  r.pressureMmHg = params.pressureMmHg;
  r.status = LeakSolveStatus::RoundLimit;
  const Vec3 fallbackAxis = ends[0]->def.direction.normalized();
  for (int round = 0; round < params.maxRounds; ++round) {
    SpringControls controls;

    // the pressure, frozen at this round's wall: a soft spring pulling each loaded node with F
    const Points f = lumenPressureForces(model, state.x, ends, pressure);
    for (int i = 0; i < n; ++i) {
      if (model.isFixed(i) || f.col(i).isZero(0.0)) continue;
      PointSpring s;
      s.nodes[0] = i;
      s.weights[0] = 1.0;
      s.anchor = state.x.col(i) + f.col(i) / kp;
      s.k = kp;
      controls.springs.push_back(s);
    }

    // the ties: stretched ones hold their points `length` apart along their direction now,
    // slack ones only carry their knot node along with their first point
    r.slackTies = 0;
    for (std::size_t i = 0; i < ties.size(); ++i) {
      const LeakTie& t = ties[i];
      const int knot = n + static_cast<int>(i);
      const Vec3 pa = leakPointAt(model, state.x, t.a);
      const Vec3 pb = leakPointAt(model, state.x, t.b);
      const double apart = (pb - pa).norm();
      const Vec3 u = apart > 1e-12 ? Vec3((pb - pa) / apart) : fallbackAxis;
      if (apart <= t.length) {
        ++r.slackTies;
        controls.springs.push_back(leakTieHalf(model, knot, t.a, 1.0, Vec3::Zero(), 2.0 * tieK));
        continue;
      }
      controls.springs.push_back(
          leakTieHalf(model, knot, t.a, 1.0, 0.5 * t.length * u, 2.0 * tieK));
      controls.springs.push_back(
          leakTieHalf(model, knot, t.b, -1.0, 0.5 * t.length * u, 2.0 * tieK));
    }

    // the lips against each other, the lumen's walls against each other; a node the solve
    // carried into a face it had no term for adds one (its normal from before the solve, when
    // it was still outside) and the solve goes again, as a scene step does (scene.cpp)
    std::vector<collide::TissueContactPair> pairs;
    if (params.contact) pairs = contact.near(state.x);
    for (const auto& pair : pairs) controls.springs.push_back(contact.spring(pair, state.x));
    const Points before = state.x;
    SolveReport report;
    for (int again = 0; again < kLeakContactSolves; ++again) {
      report = solver->solve(model, state, controls, budget);
      if (report.status == SolveStatus::Diverged || report.status == SolveStatus::InvalidInput)
        break;
      bool added = false;
      if (!params.contact) break;
      for (const auto& v : contact.violations(state.x)) {
        if (std::find(pairs.begin(), pairs.end(), v) != pairs.end()) continue;
        pairs.push_back(v);
        controls.springs.push_back(contact.spring(v, before));
        added = true;
      }
      if (!added) break;
    }
    r.rounds = round + 1;
    if (report.status == SolveStatus::Diverged || report.status == SolveStatus::InvalidInput) {
      state.x = before;
      r.status = LeakSolveStatus::SolverFailed;
      break;
    }
    const double moved = (state.x.leftCols(n) - before.leftCols(n)).colwise().norm().maxCoeff();
    if (moved < params.tolerance) {
      r.status = LeakSolveStatus::Converged;
      break;
    }
  }

  // the suture line, pressurised
  r.x = state.x.leftCols(n);
  r.line = sutureLine(def, r.x, params);
  r.thresholdMm = params.leakGapWalls * ends[0]->def.wallThickness;
  const auto widest = std::max_element(
      r.line.begin(), r.line.end(), [](const auto& a, const auto& b) { return a.gapMm < b.gapMm; });
  r.largestGapMm = widest->gapMm;
  r.angleDeg = widest->angleDeg;
  const LeakFrame frame = leakFrame(def, *ends[0], params);
  const Vec3 d = frame.direction(r.angleDeg);
  r.point = 0.5 * (collide::cutRingLip(def.tissue.model, r.x, *ends[0], d, VesselHull::Outer) +
                   collide::cutRingLip(def.tissue.model, r.x, *ends[1], d, VesselHull::Outer));
  r.leak = r.largestGapMm > r.thresholdMm;
  return r;
}

std::vector<LeakTie> sutureTies(const Scene& scene) {
  const suture::SutureModel* model = scene.sutureModel();
  const suture::SutureState* state = scene.sutureState();
  if (model == nullptr || state == nullptr) return {};
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

std::optional<LeakResult> leakTest(const Scene& scene, const LeakTestParams& params) {
  return leakTest(scene.def(), scene.tissueState().x, sutureTies(scene), params);
}

}  // namespace microsim::sim
