#include "microsim/sim/suture/suture_coupling.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <optional>
#include <utility>

namespace microsim::sim::suture {

Vec3 tissuePoint(const SpringModel& tissue, const Points& tissueX, int face,
                 const Vec3& barycentric) {
  const std::array<int, 3>& t = tissue.triangles()[static_cast<std::size_t>(face)];
  return barycentric.x() * tissueX.col(t[0]) + barycentric.y() * tissueX.col(t[1]) +
         barycentric.z() * tissueX.col(t[2]);
}

void readPiercePoints(const SpringModel& tissue, const Points& tissueX, SutureState& state) {
  for (Pierce& p : state.pierces) p.point = tissuePoint(tissue, tissueX, p.face, p.barycentric);
}

namespace {

// the arc length from node 0 to curve parameter t (node index + fraction) (mm)
double arcTo(const SutureModel& model, double t) {
  const int node = std::clamp(static_cast<int>(t), 0, model.linkCount() - 1);
  return model.arc(0, node) + (t - node) * model.rest(node);
}

Vec3 pointAt(const Points& x, double t) {
  const int node = std::clamp(static_cast<int>(t), 0, static_cast<int>(x.cols()) - 2);
  const double f = t - node;
  return (1.0 - f) * x.col(node) + f * x.col(node + 1);
}

// The pierces between the hard constraints cs[a] and cs[b] of one piece, tied over by `knot`:
// each is pulled along its straight path from the knot's first passage through the holes to
// its last, by what the hands reach past the thread from a to b can give (one tension through
// frictionless holes). False when the knot does not lie over exactly those pierces.
bool pullThroughKnot(const SutureModel& model, const SutureState& state,
                     const std::vector<ChainConstraint>& cs, std::size_t a, std::size_t b,
                     const KnotOverStitch& knot, std::vector<PierceTension>& tensions) {
  if (b < a + 2 || cs[a].node >= knot.first || cs[b].node <= knot.last) return false;
  if (cs[a + 1].node <= knot.first || cs[b - 1].node >= knot.last) return false;
  // the path: the near grip, the knot, the holes, the knot, the far grip
  std::vector<Vec3> path{cs[a].position, pointAt(state.x, knot.first)};
  for (std::size_t k = a + 1; k < b; ++k) path.push_back(cs[k].position);
  path.push_back(pointAt(state.x, knot.last));
  path.push_back(cs[b].position);
  double length = 0.0;
  for (std::size_t k = 1; k < path.size(); ++k) length += (path[k] - path[k - 1]).norm();
  const double excess = length + knot.wrap - model.arc(cs[a].node, cs[b].node);
  // taut within a link, as a straight side is (suture_coupling.h)
  if (excess < -model.rest(cs[a + 1].node)) return true;
  for (std::size_t k = a + 1; k < b; ++k) {
    const Vec3& at = cs[k].position;
    Vec3 pull = Vec3::Zero();
    for (const Vec3& q : {path[k - a], path[k - a + 2]})
      if ((q - at).norm() > 0.0) pull += (q - at).normalized();
    PierceTension& t = tensions[static_cast<std::size_t>(cs[k].source)];
    t.pull = std::max(excess, 0.0) * pull;
    t.taut = true;
  }
  return true;
}

}  // namespace

double knotWrap(const SutureModel& model, const SutureState& state, double first, double last) {
  std::vector<std::pair<int, Vec3>> between;
  for (const Pierce& p : state.pierces)
    if (p.node > first && p.node < last) between.emplace_back(p.node, p.point);
  std::sort(between.begin(), between.end(),
            [](const auto& l, const auto& r) { return l.first < r.first; });
  Vec3 from = pointAt(state.x, first);
  double straight = 0.0;
  for (const auto& [node, point] : between) {
    straight += (point - from).norm();
    from = point;
  }
  straight += (pointAt(state.x, last) - from).norm();
  return arcTo(model, last) - arcTo(model, first) - straight;
}

std::vector<PierceTension> pierceTensions(const SutureModel& model, const SutureState& state,
                                          std::span<const Grip> grips,
                                          const std::optional<KnotOverStitch>& knot) {
  std::vector<PierceTension> tensions(state.pierces.size());
  for (const Piece& piece : chainPieces(state.alive)) {
    const std::vector<ChainConstraint> cs = pieceConstraints(model, state, grips, piece);
    // a knot tied over pierces between two grips carries the hands' pull to them (`done`
    // stays empty without a knot: nothing to mark on the common path)
    std::vector<std::uint8_t> done;
    if (knot) {
      done.assign(cs.size(), 0);
      for (std::size_t a = 0, b = 1; b < cs.size(); ++b) {
        if (!cs[b].hard) continue;
        if (cs[a].hard && pullThroughKnot(model, state, cs, a, b, *knot, tensions))
          std::fill(done.begin() + static_cast<std::ptrdiff_t>(a),
                    done.begin() + static_cast<std::ptrdiff_t>(b), 1);
        a = b;
      }
    }
    // a pierce with only pierces between it and a free end carries no tension: that end
    // feeds thread through them as fast as it is drawn (they slide, suture_constraints.h)
    std::size_t firstHard = cs.size(), lastHard = 0;
    for (std::size_t k = 0; k < cs.size(); ++k)
      if (cs[k].hard) {
        firstHard = std::min(firstHard, k);
        lastHard = k;
      }
    for (std::size_t k = 0; k < cs.size(); ++k) {
      if (cs[k].hard || (!done.empty() && done[k]) || firstHard > k || lastHard < k) continue;
      // the tightest side's excess, carried by every taut side (one tension through the pierce)
      double excess = 0.0;
      Vec3 pull = Vec3::Zero();
      bool taut = false;
      for (const std::size_t q : {k - 1, k + 1}) {
        if (q >= cs.size()) continue;  // k − 1 wraps to a huge value at k = 0
        const Vec3 toQ = cs[q].position - cs[k].position;
        const double distance = toQ.norm();
        const double arc = model.arc(cs[k].node, cs[q].node);
        excess = std::max(excess, distance - arc);
        const int link = std::min(cs[k].node, cs[q].node);
        if (distance > 0.0 && distance >= arc - model.rest(link)) {
          pull += toQ / distance;
          taut = true;
        }
      }
      PierceTension& t = tensions[static_cast<std::size_t>(cs[k].source)];
      t.pull = excess * pull;
      t.taut = taut;
    }
  }
  return tensions;
}

SpringControls couplingControls(const SpringModel& tissue, const Points& tissueX,
                                const SutureModel& model, const SutureState& state,
                                std::span<const Grip> grips, const CouplingParams& params,
                                const std::optional<KnotOverStitch>& knot) {
  const std::vector<PierceTension> tensions = pierceTensions(model, state, grips, knot);

  // average the pulls that reach each free corner node (ordered map: deterministic); a taut
  // pierce with nothing left to take holds its face where it is, so that the tissue does not
  // spring back only to be pulled again on the next frame
  std::map<int, std::pair<Vec3, int>> perNode;
  for (std::size_t k = 0; k < tensions.size(); ++k) {
    const Pierce& p = state.pierces[k];
    // how far the thread led the hole past the tissue's point (0 unless it gave way)
    const Vec3 led = (p.point - tissuePoint(tissue, tissueX, p.face, p.barycentric)) / params.gain;
    if (!tensions[k].taut && tensions[k].pull.isZero(0.0) && led.isZero(0.0)) continue;
    for (int node : tissue.triangles()[static_cast<std::size_t>(p.face)]) {
      if (tissue.isFixed(node)) continue;
      auto [it, inserted] = perNode.try_emplace(node, Vec3::Zero(), 0);
      it->second.first += tensions[k].pull + led;
      it->second.second += 1;
    }
  }

  SpringControls controls;
  for (const auto& [node, sum] : perNode)
    controls.add(node, Vec3(tissueX.col(node)) + params.gain * sum.first / sum.second);
  return controls;
}

namespace {

/// The point of the needle polyline (nodes 0..swage) nearest p (mm); none when that is the
/// tip itself with p beyond it: the needle has been drawn back out of the hole.
std::optional<Vec3> couplingNeedlePoint(const SutureModel& model, const Points& x, const Vec3& p) {
  Vec3 best = x.col(0);
  bool beyondTip = true;
  for (int k = 0; k < model.swage(); ++k) {
    const Vec3 a = x.col(k);
    const Vec3 d = x.col(k + 1) - a;
    const double squared = d.squaredNorm();
    const double along = squared > 0.0 ? (p - a).dot(d) / squared : 0.0;
    const double t = std::clamp(along, 0.0, 1.0);
    if ((a + t * d - p).squaredNorm() < (best - p).squaredNorm()) {
      best = a + t * d;
      beyondTip = false;
    } else if (k == 0) {
      beyondTip = along < 0.0;
    }
  }
  if (beyondTip) return std::nullopt;
  return best;
}

}  // namespace

std::vector<PointSpring> couplingSprings(const SpringModel& tissue, const Points& tissueX,
                                         const SutureModel& model, const SutureState& state,
                                         std::span<const Grip> grips, const CouplingParams& params,
                                         const std::optional<KnotOverStitch>& knot) {
  const std::vector<PierceTension> tensions = pierceTensions(model, state, grips, knot);
  std::vector<PointSpring> springs;
  for (std::size_t k = 0; k < tensions.size(); ++k) {
    const Pierce& p = state.pierces[k];
    const bool passive = model.needleLinks() > 0 && p.node < model.swage();
    // a hole that gave way to the thread (led) is pulled where the thread left it
    const bool led = p.point != tissuePoint(tissue, tissueX, p.face, p.barycentric);
    if (!passive && !led && !tensions[k].taut && tensions[k].pull.isZero(0.0)) continue;
    const std::optional<Vec3> onNeedle = passive ? couplingNeedlePoint(model, state.x, p.point) : std::nullopt;
    if (passive && !onNeedle) continue;
    const std::array<int, 3>& t = tissue.triangles()[static_cast<std::size_t>(p.face)];
    PointSpring s;
    for (std::size_t c = 0; c < 3; ++c) {
      s.nodes[c] = t[c];
      s.weights[c] = p.barycentric[static_cast<Eigen::Index>(c)];
    }
    // a hole the needle passes through stays on the needle; a thread pulls its hole
    // p.point: the tissue's point as read at the step's start, or where the thread led it
    s.anchor = passive ? *onNeedle : Vec3(p.point + params.gain * tensions[k].pull);
    s.k = params.stiffness;
    springs.push_back(s);
  }
  return springs;
}

}  // namespace microsim::sim::suture
