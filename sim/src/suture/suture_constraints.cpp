#include "microsim/sim/suture/suture_constraints.h"

#include <Eigen/SVD>

#include <algorithm>
#include <limits>
#include <numeric>
#include <utility>

namespace microsim::sim::suture {

namespace {

bool activePierce(const SutureModel& model, const Pierce& p) {
  return p.node >= model.swage();
}

// stretch of the side from pierce node c to neighbour (node q at Q); free end: 0
double sideStretch(const SutureModel& model, int c, const Vec3& p, const ChainConstraint* q) {
  if (q == nullptr) return 0.0;
  const double distance = (p - q->position).norm();
  const double arc = model.arc(c, q->node);
  if (arc <= 0.0) return distance > 0.0 ? std::numeric_limits<double>::max() : 0.0;
  return distance / arc;
}

// where the needle (the polyline of nodes 0..swage) passes nearest a point: the nearer end
// node of the nearest segment (the lowest index on ties), and the distance (mm)
struct NeedlePoint {
  int node = 0;
  double distance = 0.0;
};

NeedlePoint nearestNeedlePoint(const SutureModel& model, const Points& x, const Vec3& p) {
  NeedlePoint best{0, (x.col(0) - p).norm()};
  for (int k = 0; k < model.swage(); ++k) {
    const Vec3 a = x.col(k);
    const Vec3 d = x.col(k + 1) - a;
    const double squared = d.squaredNorm();
    const double t = squared > 0.0 ? std::clamp((p - a).dot(d) / squared, 0.0, 1.0) : 0.0;
    const double distance = (a + t * d - p).norm();
    if (distance < best.distance) best = {t < 0.5 ? k : k + 1, distance};
  }
  return best;
}

// pierce indices in path order from the tip: by node; on one node (pierces the needle carries)
// the later-made first, since the tip made it after the others and nearer itself
std::vector<int> piercePathOrder(const std::vector<Pierce>& pierces) {
  std::vector<int> order(pierces.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    const int na = pierces[static_cast<std::size_t>(a)].node;
    const int nb = pierces[static_cast<std::size_t>(b)].node;
    return na != nb ? na < nb : a > b;
  });
  return order;
}

// by node, a hard constraint before a soft one on the same node
void sortInNodeOrder(std::vector<ChainConstraint>& cs) {
  std::stable_sort(cs.begin(), cs.end(), [](const ChainConstraint& a, const ChainConstraint& b) {
    return a.node != b.node ? a.node < b.node : a.hard > b.hard;
  });
}

// Σ (r_k − rc)(x_k − xc)ᵀ over the first `count` nodes, summed node by node. Written out
// rather than as one Eigen product: with a dynamic inner size Eigen's blocked matrix product
// picks its summation order per build (clang's loop unrolling moved a result by an ulp, so a
// replay's state hash differed between compilers) and allocates its blocking buffers.
Eigen::Matrix3d crossCovariance(const Points& r, const Vec3& rc, const Points& x, const Vec3& xc,
                                int count) {
  Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
  for (int k = 0; k < count; ++k) h.noalias() += (r.col(k) - rc) * (x.col(k) - xc).transpose();
  return h;
}

// Draws the thread one node through the run of pierces that starts at cs[k] and goes on in
// direction `step` (+1: towards higher nodes, −1: lower) while each sits on the node next to
// the one before (the holes of a wall thinner than a link) or the thread between them is
// taut (it has no slack to give the hole behind): every pierce of the run moves one
// node that way, so the side behind cs[k] gains a link and the side ahead of the run loses
// one; the sides within the run keep theirs. Done only when it lowers the larger stretch of
// those two outer sides, and when the node past the run is free thread (not a grip, not past
// the piece's end, not the needle). A run ends short of turns wound on a forceps' jaws: the
// side to them loses the link, and the length restore draws the turns along the jaws after it.
// `behind` is cs[k]'s neighbour on the far side from `step` as slidePierces measures it (the swage
// for a grip on the needle). True when done.
bool pushRun(const SutureModel& model, std::vector<ChainConstraint>& cs, std::size_t k, int step,
             const ChainConstraint* behind, const Piece& piece, double slideTolerance) {
  const auto index = [&](std::size_t j) { return static_cast<std::ptrdiff_t>(j) + step; };
  const auto inRange = [&](std::ptrdiff_t j) {
    return j >= 0 && j < static_cast<std::ptrdiff_t>(cs.size());
  };
  // the run: on through each next pierce that sits on the next node, or whose side from the
  // one before would be taut once that one moved (the thread between them has none to give)
  std::size_t last = k;
  while (inRange(index(last))) {
    const ChainConstraint& next = cs[static_cast<std::size_t>(index(last))];
    const bool adjacent = next.node == cs[last].node + step;
    const bool taut =
        sideStretch(model, cs[last].node + step, cs[last].position, &next) > 1.0 + slideTolerance;
    if (!adjacent && !taut) break;
    if (next.wound) break;  // the turns give thread: the side to them gives the link
    if (next.hard) return false;
    last = static_cast<std::size_t>(index(last));
  }
  const ChainConstraint* ahead =
      inRange(index(last)) ? &cs[static_cast<std::size_t>(index(last))] : nullptr;
  const int target = cs[last].node + step;
  if (target > piece.last || target < std::max(piece.first, model.swage())) return false;
  if (ahead && (ahead->node - target) * step <= 0) return false;
  const auto stretchAt = [&](int shift) {
    const double back = sideStretch(model, cs[k].node + shift, cs[k].position, behind);
    const double front = sideStretch(model, cs[last].node + shift, cs[last].position, ahead);
    return std::max(back, front);
  };
  if (stretchAt(step) >= stretchAt(0)) return false;
  for (std::size_t j = k;; j = static_cast<std::size_t>(index(j))) {
    cs[j].node += step;
    if (j == last) break;
  }
  return true;
}

// the ends of the wound runs in the piece, as hard constraints where they are, kept in node order
void addWoundEnds(const Points& x, std::span<const std::array<int, 2>> wound, const Piece& piece,
                  std::vector<ChainConstraint>& cs) {
  const std::size_t before = cs.size();
  for (const std::array<int, 2>& run : wound)
    for (const int node : {run[0], run[1]})
      if (node >= piece.first && node <= piece.last)
        cs.push_back({node, x.col(node), true, -1, true});
  if (cs.size() != before) sortInNodeOrder(cs);
}

}  // namespace

bool gripHoldsNeedle(const SutureModel& model, const Grip& grip) {
  return model.needleLinks() > 0 &&
         (grip.node < model.swage() || (grip.node == model.swage() && grip.fraction == 0.0));
}

Vec3 gripPoint(const Points& x, const Grip& grip) {
  if (grip.fraction == 0.0) return x.col(grip.node);
  return (1.0 - grip.fraction) * x.col(grip.node) + grip.fraction * x.col(grip.node + 1);
}

std::array<Vec3, 2> clampedLinkEnds(const SutureModel& model, const Grip& grip, const Vec3& point,
                                    const Vec3& direction) {
  const double length = model.rest(grip.node);
  return {point - grip.fraction * length * direction,
          point + (1.0 - grip.fraction) * length * direction};
}

std::vector<ChainConstraint> pieceConstraints(const SutureModel& model, const SutureState& state,
                                              std::span<const Grip> grips, const Piece& piece) {
  std::vector<ChainConstraint> out;
  for (std::size_t g = 0; g < grips.size(); ++g) {
    const Grip& grip = grips[g];
    if (grip.fraction == 0.0) {
      if (grip.node >= piece.first && grip.node <= piece.last)
        out.push_back({grip.node, grip.position, true, static_cast<int>(g)});
    } else if (grip.node >= piece.first && grip.node + 1 <= piece.last) {
      out.push_back({grip.node, state.x.col(grip.node), true, static_cast<int>(g)});
      out.push_back({grip.node + 1, state.x.col(grip.node + 1), true, static_cast<int>(g)});
    }
  }
  for (std::size_t k = 0; k < state.pierces.size(); ++k) {
    const Pierce& p = state.pierces[k];
    if (activePierce(model, p) && p.node >= piece.first && p.node <= piece.last)
      out.push_back({p.node, p.point, false, static_cast<int>(k)});
  }
  sortInNodeOrder(out);
  return out;
}

int slidePierces(const SutureModel& model, SutureState& state, std::span<const Grip> grips,
                 double slideTolerance, std::vector<SutureEvent>& events,
                 std::span<const std::array<int, 2>> wound) {
  int slides = 0;
  const int swage = model.swage();
  std::vector<std::pair<int, SutureEventKind>> removed;

  // passive pierces, from the one farthest along the chain to the tip: each follows the
  // needle node nearest its point, but never onto or past the node of the pierce ahead of it
  // (a thread node holds one pierce; needle nodes may carry several); one the needle has left
  // is released
  int ceiling = model.nodeCount() - 1;
  const std::vector<int> order = piercePathOrder(state.pierces);
  for (auto it = order.rbegin(); it != order.rend(); ++it) {
    Pierce& p = state.pierces[static_cast<std::size_t>(*it)];
    if (!activePierce(model, p)) {
      const NeedlePoint near = nearestNeedlePoint(model, state.x, p.point);
      if (near.distance > model.def().pierceReleaseDistance) {
        removed.emplace_back(*it, SutureEventKind::Released);
        continue;
      }
      p.node = std::min(near.node, ceiling);
    }
    ceiling = p.node >= swage ? p.node - 1 : p.node;
  }

  for (const Piece& piece : chainPieces(state.alive)) {
    std::vector<ChainConstraint> cs = pieceConstraints(model, state, grips, piece);
    addWoundEnds(state.x, wound, piece, cs);
    for (std::size_t k = 0; k < cs.size(); ++k) {
      if (cs[k].hard) continue;
      ChainConstraint& me = cs[k];
      const ChainConstraint* left = k > 0 ? &cs[k - 1] : nullptr;
      const ChainConstraint* right = k + 1 < cs.size() ? &cs[k + 1] : nullptr;
      // a grip on the needle holds it rigid up to the swage: the thread on that side spans
      // from the swage, where the needle puts it (measured from the grip, through the needle's
      // arc, the side could never be taut and the pierce stayed at the swage, towing its wall)
      const ChainConstraint swageEnd{swage, state.x.col(swage), true};
      const ChainConstraint* leftEnd = left && left->node < swage ? &swageEnd : left;
      // the node may not pass its neighbours (pierces keep their order), nor leave the thread:
      // the rigid needle cannot slide through a pierce backwards
      const auto lo = [&] { return std::max(left ? left->node + 1 : piece.first, swage); };
      const auto hi = [&] { return right ? right->node - 1 : piece.last; };
      const auto worst = [&](int c) {
        return std::max(sideStretch(model, c, me.position, leftEnd),
                        sideStretch(model, c, me.position, right));
      };
      // slide one node at a time while it lowers the tighter side's stretch
      bool out = false;
      for (;;) {
        const double sl = sideStretch(model, me.node, me.position, leftEnd);
        const double sr = sideStretch(model, me.node, me.position, right);
        if (std::max(sl, sr) <= 1.0 + slideTolerance) break;
        const int next = sr > sl ? me.node - 1 : me.node + 1;
        if (next >= lo() && next <= hi() && worst(next) < worst(me.node)) {
          me.node = next;
          ++slides;
          continue;
        }
        if (next < lo() || next > hi()) {
          // past a free end the suture leaves the pierce
          out = (next < lo() && !left && lo() == piece.first) || (next > hi() && !right);
          if (out) break;
        }
        // alone it cannot slide: the thread has to go through the next hole as well (the side
        // to it would be over-stretched: a wall's two holes, a taut stretch across the
        // lumen), so it is drawn through both together, and on through the run (pushRun). A
        // side to a pierce on the neighbouring node spans the wall between two holes: no
        // slide of this hole alone shortens it (a wall thicker than a link keeps it stretched,
        // and the rule above has already tried to give it a second link), so it does not
        // decide which way the thread goes; the side beyond does.
        const auto pulling = [&](const ChainConstraint* q, double stretch) {
          return q && !q->hard && std::abs(q->node - me.node) == 1 ? 1.0 : stretch;
        };
        const double pl = pulling(left, sl);
        const double pr = pulling(right, sr);
        if (std::max(pl, pr) <= 1.0 + slideTolerance) break;
        const int step = pr > pl ? -1 : 1;
        const ChainConstraint* ahead = step < 0 ? left : right;
        if (!ahead || ahead->hard) break;
        if (!pushRun(model, cs, k, step, step > 0 ? leftEnd : right, piece, slideTolerance)) break;
        for (const ChainConstraint& c : cs)
          if (!c.hard) state.pierces[static_cast<std::size_t>(c.source)].node = c.node;
        ++slides;
      }
      state.pierces[static_cast<std::size_t>(me.source)].node = me.node;
      if (out) removed.emplace_back(me.source, SutureEventKind::PulledOut);
    }
  }

  // remove released and pulled-out pierces, highest index first so earlier indices stay valid
  std::sort(removed.begin(), removed.end());
  for (auto it = removed.rbegin(); it != removed.rend(); ++it) {
    events.push_back({it->second, -1, it->first, state.time});
    state.pierces.erase(state.pierces.begin() + it->first);
  }
  return slides;
}

std::optional<int> findBreak(const SutureModel& model, const SutureState& state,
                             std::span<const Grip> grips) {
  const double limit = 1.0 + model.def().breakStretch;
  for (const Piece& piece : chainPieces(state.alive)) {
    const std::vector<ChainConstraint> cs = pieceConstraints(model, state, grips, piece);
    std::size_t from = cs.size();
    double path = 0.0;
    for (std::size_t k = 0; k < cs.size(); ++k) {
      if (from < cs.size()) path += (cs[k].position - cs[k - 1].position).norm();
      if (!cs[k].hard) continue;
      // a pair of grips: the path through the pierces between them against the rest arc
      if (from < cs.size() && cs[k].node > cs[from].node &&
          path > model.arc(cs[from].node, cs[k].node) * limit) {
        // the needle is rigid: only thread links break
        const int firstLink = std::max(cs[from].node, std::min(model.swage(), cs[k].node - 1));
        int worst = firstLink;
        double worstStretch = -std::numeric_limits<double>::infinity();
        for (int l = firstLink; l < cs[k].node; ++l) {
          const double s = (state.x.col(l + 1) - state.x.col(l)).norm() / model.rest(l);
          if (s > worstStretch) {
            worstStretch = s;
            worst = l;
          }
        }
        return worst;
      }
      from = k;
      path = 0.0;
    }
  }
  return std::nullopt;
}

Eigen::Matrix3d needleRotation(const SutureModel& model, const Points& x) {
  const int n = model.needleLinks();
  if (n == 0) return Eigen::Matrix3d::Identity();
  const Points& r = model.needleShape();
  const Vec3 rc = r.rowwise().mean();
  const Vec3 xc = x.leftCols(n + 1).rowwise().mean();
  const Eigen::Matrix3d h = crossCovariance(r, rc, x, xc, n + 1);
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  d(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  return svd.matrixV() * d * svd.matrixU().transpose();
}

void rigidifyNeedle(const SutureModel& model, Points& x, int anchor,
                    const Eigen::Matrix3d* rotation) {
  const int n = model.needleLinks();
  if (n == 0) return;
  const Points& r = model.needleShape();
  Eigen::Matrix3d rot;
  if (rotation) {
    rot = *rotation;
  } else {
    // best rotation about the anchor (Kabsch on offsets from it)
    const Eigen::Matrix3d h = crossCovariance(r, r.col(anchor), x, x.col(anchor), n + 1);
    Eigen::JacobiSVD<Eigen::Matrix3d> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
    d(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
    rot = svd.matrixV() * d * svd.matrixU().transpose();
  }
  const Vec3 origin = x.col(anchor);
  for (int k = 0; k <= n; ++k)
    if (k != anchor) x.col(k) = origin + rot * (r.col(k) - r.col(anchor));
}

}  // namespace microsim::sim::suture
