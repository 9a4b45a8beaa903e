#include "microsim/sim/suture/suture_solver.h"

#include "microsim/sim/suture/knot_strain.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <iterator>

namespace microsim::sim::suture {

namespace {

bool finite(const Points& x) { return x.allFinite(); }

// an active pierce whose hole gives way to the thread this step (SutureWorld::yieldingBetween)
bool yields(const SutureWorld& world, const Pierce& p) {
  return world.yieldingBetween && p.node > (*world.yieldingBetween)[0] &&
         p.node < (*world.yieldingBetween)[1];
}

// sorted by node, the first of several on one node kept
void inNodeOrderOnce(std::vector<Leader>& leaders) {
  std::stable_sort(leaders.begin(), leaders.end(),
                   [](const Leader& a, const Leader& b) { return a.node < b.node; });
  leaders.erase(std::unique(leaders.begin(), leaders.end(),
                            [](const Leader& a, const Leader& b) { return a.node == b.node; }),
                leaders.end());
}

// Sliding is how this chain draws thread through a hole: the hole moves on to the next node
// (suture_constraints.h), and the substep after puts that node on the hole. Through a free tail
// the next substep then carried the whole tail a link (0.15 mm) in one substep and kept that as
// speed: each link the hole slid by whipped the tail, and the tail drawn after the shipped
// stitch's needle piled up within 0.8 mm of the entry. So a free tail beyond the outermost
// hole of its piece that slid d nodes along it is re-laid d nodes on at once: node i takes the
// place and the previous place of node i − d (the tail keeps its shape and its speed; its end
// draws back d links), so the new hole node lies on the hole. The d nodes that came to the drawn
// side keep theirs; the next substep lays them out. A tail that touches itself (a throw in it)
// is left alone: re-laid, its thread would slide through its own knot.
void relayFreeTails(const SutureModel& model, SutureState& state, std::span<const int> before,
                    std::span<const Grip> grips, std::span<const std::uint8_t> selfTouched) {
  if (before.size() != state.pierces.size()) return;  // a hole released: nothing to follow
  const int swage = model.swage();
  const auto gripped = [&](int a, int b) {
    for (const Grip& g : grips)
      if ((g.fraction > 0.0 ? g.node + 1 : g.node) >= a && g.node <= b) return true;
    return false;
  };
  const auto touched = [&](int a, int b) {
    for (int i = a; i <= b; ++i)
      if (selfTouched[static_cast<std::size_t>(i)]) return true;
    return false;
  };
  const auto relay = [&](int node, int from) {
    state.x.col(node) = state.x.col(from);
    state.xPrev.col(node) = state.xPrev.col(from);
  };
  for (const Piece& piece : chainPieces(state.alive)) {
    const auto inPiece = [&](int n) { return n >= swage && n >= piece.first && n <= piece.last; };
    int hiNow = -1, hiBefore = -1;
    int loNow = piece.last + 1, loBefore = piece.last + 1;
    bool same = true;  // the same holes hold thread in this piece before and after
    for (std::size_t k = 0; k < state.pierces.size(); ++k) {
      const int now = state.pierces[k].node;
      if (inPiece(now) != inPiece(before[k])) same = false;
      if (!inPiece(now) || !inPiece(before[k])) continue;
      hiNow = std::max(hiNow, now);
      hiBefore = std::max(hiBefore, before[k]);
      loNow = std::min(loNow, now);
      loBefore = std::min(loBefore, before[k]);
    }
    if (!same || hiNow < 0) continue;
    const int up = hiNow - hiBefore;
    if (up > 0 && !gripped(hiBefore, piece.last) && !touched(hiBefore, piece.last))
      for (int i = piece.last; i >= hiNow; --i) relay(i, i - up);
    // towards the low end only where it is free thread, not the needle
    const int down = loBefore - loNow;
    const bool lowFree = model.needleLinks() == 0 || piece.first > swage;
    if (down > 0 && lowFree && !gripped(piece.first, loBefore) && !touched(piece.first, loBefore))
      for (int i = piece.first; i <= loNow; ++i) relay(i, i + down);
  }
}

bool validInput(const SutureModel& model, const SutureState& state, std::span<const Grip> grips,
                const SutureStepParams& params) {
  if (state.x.cols() != model.nodeCount() || state.xPrev.cols() != model.nodeCount() ||
      static_cast<int>(state.alive.size()) != model.linkCount())
    return false;
  if (!finite(state.x) || !finite(state.xPrev)) return false;
  if (!(params.dt > 0.0) || !std::isfinite(params.dt) || params.substeps < 1 ||
      params.iterations < 1 || !std::isfinite(params.maxSubstepMotion) ||
      !std::isfinite(state.substep) || state.substep < 0.0)
    return false;
  for (const Grip& g : grips) {
    if (g.node < 0 || g.node >= model.nodeCount() || !g.position.allFinite() ||
        !g.rotation.allFinite() || !(g.fraction >= 0.0 && g.fraction < 1.0))
      return false;
    if (g.fraction == 0.0) continue;
    // between two nodes: an intact link; on the thread, the direction it is clamped along
    if (g.node + 1 >= model.nodeCount() || !state.alive[static_cast<std::size_t>(g.node)]) return false;
    if (!gripHoldsNeedle(model, g) && !(g.direction.allFinite() && g.direction.norm() > 0.0)) return false;
  }
  for (const Pierce& p : state.pierces)
    if (p.node < 0 || p.node >= model.nodeCount() || !p.point.allFinite()) return false;
  return true;
}

// leaders plus contact nodes (at their current positions), sorted by node, into `out`
void withContacts(std::span<const Leader> leaders, const Points& x,
                  const std::vector<std::uint8_t>& contact, std::vector<Leader>& out) {
  out.clear();
  std::size_t k = 0;
  for (int i = 0; i < static_cast<int>(contact.size()); ++i) {
    if (k < leaders.size() && leaders[k].node == i) {
      out.push_back(leaders[k++]);
    } else if (contact[static_cast<std::size_t>(i)]) {
      out.push_back({i, x.col(i)});
    }
  }
}

// the paper's follow-the-leader; a piece nothing holds follows its first node
class FollowTheLeaderSolver final : public SutureSolver {
 public:
  std::string_view name() const override { return "ftl"; }

 protected:
  bool restoreLengths(const SutureModel& model, Points& x, const std::vector<std::uint8_t>& alive,
                      std::span<const Leader> leaders, const std::vector<std::uint8_t>& contact,
                      const SutureStepParams&, int) override {
    std::vector<Leader>& all = all_;
    withContacts(leaders, x, contact, all);
    for (const Piece& piece : chainPieces(alive)) {
      const bool held = std::any_of(all.begin(), all.end(), [&](const Leader& l) {
        return l.node >= piece.first && l.node <= piece.last;
      });
      if (!held) all.push_back({piece.first, x.col(piece.first)});
    }
    std::sort(all.begin(), all.end(), [](const Leader& a, const Leader& b) { return a.node < b.node; });
    followTheLeader(model, x, alive, all);
    return true;
  }

 private:
  std::vector<Leader> all_;
};

// true when a piece of the chain has an end beyond its outermost leaders (leaders sorted)
bool hasFreeEnd(const std::vector<std::uint8_t>& alive, std::span<const Leader> leaders) {
  for (const Piece& piece : chainPieces(alive)) {
    const auto first = std::find_if(leaders.begin(), leaders.end(),
                                    [&](const Leader& l) { return l.node >= piece.first; });
    if (first == leaders.end() || first->node != piece.first) return true;
    const auto last = std::find_if(first, leaders.end(),
                                   [&](const Leader& l) { return l.node > piece.last; });
    if (std::prev(last)->node != piece.last) return true;
  }
  return false;
}

// exact lengths by the tridiagonal projection, follow-the-leader outward as fallback predictor
class DirectSolver final : public SutureSolver {
 public:
  std::string_view name() const override { return "direct"; }

 protected:
  bool restoreLengths(const SutureModel& model, Points& x, const std::vector<std::uint8_t>& alive,
                      std::span<const Leader> leaders, const std::vector<std::uint8_t>& contact,
                      const SutureStepParams& params, int round) override {
    // after a round that did not converge (a fold the projection cannot undo), the paper's
    // two averaged passes re-lay the spans between leaders
    withContacts(leaders, x, contact, all_);
    const bool relaid = round > 0 && !converged_;
    if (relaid) followTheLeader(model, x, alive, all_);

    // weights: thread nodes 1, leaders 0, contact nodes scaled down
    const double unit = model.inverseMass(model.nodeCount() - 1);
    w_.resize(static_cast<std::size_t>(model.nodeCount()));
    for (int i = 0; i < model.nodeCount(); ++i)
      w_[static_cast<std::size_t>(i)] =
          model.inverseMass(i) / unit * (contact[static_cast<std::size_t>(i)] ? params.contactWeight : 1.0);
    for (const Leader& l : leaders) w_[static_cast<std::size_t>(l.node)] = 0.0;
    // the projection alone first: its mass-weighted corrections add no energy, whereas
    // follow-the-leader outward of the last leader moves each node entirely onto its already
    // placed neighbour and, carried on as Verlet velocity, whips a free tail until it explodes
    // (a 2000-link tail reached 70 mm per substep within ten 10 ms frames). Follow-the-leader
    // outward stays the fallback predictor for a jump the projection cannot take from where the
    // chain is.
    ChainProjectionResult r = projectChainLengths(
        x, model.restLengths(), w_, alive, params.projectionIterations, params.projectionTolerance,
        scratch_);
    if (r.residual > params.projectionTolerance && !relaid && hasFreeEnd(alive, all_)) {
      followOutward(model, x, alive, all_);
      r = projectChainLengths(x, model.restLengths(), w_, alive, params.projectionIterations,
                              params.projectionTolerance, scratch_);
    }
    converged_ = r.residual <= params.projectionTolerance;
    return converged_;
  }

  void carry(const SutureModel& model, Points& x, const std::vector<std::uint8_t>& alive,
             std::span<const Leader> leaders) override {
    carrySpans(model, x, alive, leaders);
  }

 private:
  std::vector<Leader> all_;
  std::vector<double> w_;
  ChainProjectionScratch scratch_;
  bool converged_ = true;
};

}  // namespace

void SutureSolver::carry(const SutureModel&, Points&, const std::vector<std::uint8_t>&,
                         std::span<const Leader>) {}

int SutureSolver::substepCount(const SutureModel& model, const SutureState& state,
                               std::span<const Grip> grips, const SutureStepParams& params) const {
  if (!(params.maxSubstepMotion > 0.0) || params.substeps == 1) return params.substeps;
  // the grips' moves, the needle grip's turn, the fastest node's velocity over the step
  double motion = 0.0;
  for (const Grip& g : grips) {
    motion = std::max(motion, (g.position - gripPoint(state.x, g)).norm());
    if (g.oriented && gripHoldsNeedle(model, g)) {
      const Eigen::AngleAxisd turn(g.rotation * needleRotation(model, state.x).transpose());
      const double size = model.arc(0, model.swage());
      motion = std::max(motion, std::abs(turn.angle()) * size);
    }
  }
  if (state.substep > 0.0) {
    const double fastest = (state.x - state.xPrev).colwise().squaredNorm().maxCoeff();
    motion = std::max(motion, std::sqrt(fastest) * params.dt / state.substep);
  }
  const double wanted = std::ceil(motion / params.maxSubstepMotion);
  return static_cast<int>(std::clamp(wanted, 1.0, static_cast<double>(params.substeps)));
}

SutureStepReport SutureSolver::step(const SutureModel& model, SutureState& state,
                                    std::span<const Grip> grips, const SutureWorld& world,
                                    const SutureStepParams& params) {
  SutureStepReport report;
  if (!validInput(model, state, grips, params)) {
    report.status = SutureStepStatus::InvalidInput;
    return report;
  }
  const int nodes = model.nodeCount();
  const int swage = model.swage();
  const double radius = model.def().contactRadius;
  const double mu = model.def().friction;
  if (self_.linkCount() != model.linkCount()) self_ = SelfContact(model.linkCount());
  const int selfSkip =
      std::max(2, static_cast<int>(std::ceil(2.0 * radius / model.rest(model.linkCount() - 1))) + 1);

  // where the grips start from: their points now (a clamped thread link: its direction), and
  // the needle's pose
  gripFrom_.resize(grips.size());
  clampFrom_.resize(grips.size());
  for (std::size_t g = 0; g < grips.size(); ++g) {
    gripFrom_[g] = gripPoint(state.x, grips[g]);
    if (grips[g].fraction > 0.0 && !gripHoldsNeedle(model, grips[g])) {
      const Vec3 link = state.x.col(grips[g].node + 1) - state.x.col(grips[g].node);
      clampFrom_[g] = link.norm() > 0.0 ? Vec3(link.normalized()) : Vec3(grips[g].direction.normalized());
    }
  }
  const Eigen::Quaterniond needleFrom(needleRotation(model, state.x));

  movable_.resize(static_cast<std::size_t>(nodes));
  movableSurface_.resize(static_cast<std::size_t>(nodes));
  contact_.resize(static_cast<std::size_t>(nodes));
  selfTouched_.resize(static_cast<std::size_t>(nodes));
  free_.resize(static_cast<std::size_t>(nodes));
  current_.assign(grips.begin(), grips.end());
  const int substeps = substepCount(model, state, grips, params);
  report.substeps = substeps;
  const double h = params.dt / substeps;
  const double keep = std::exp(-model.def().drag * h);

  for (int s = 0; s < substeps; ++s) {
    const double f = static_cast<double>(s + 1) / substeps;

    // predict (the velocity spans the last substep, which may have been longer or shorter)
    const double carried = keep * (state.substep > 0.0 ? h / state.substep : 1.0);
    xStart_ = state.x;
    const Vec3 fall = model.gravity * h * h;
    state.x += carried * (state.x - state.xPrev);
    state.x.colwise() += fall;
    state.xPrev = xStart_;
    state.substep = h;

    // leaders: interpolated grips (an oriented needle grip poses the needle), active pierces
    leaders_.clear();
    const Grip* needleGrip = nullptr;
    Eigen::Matrix3d needlePose = needleFrom.toRotationMatrix();
    for (std::size_t g = 0; g < grips.size(); ++g) {
      const Grip& grip = grips[g];
      current_[g].position = (1.0 - f) * gripFrom_[g] + f * grip.position;
      const bool onNeedle = gripHoldsNeedle(model, grip);
      if (grip.fraction == 0.0) {
        leaders_.push_back({grip.node, current_[g].position});
      } else if (!onNeedle) {
        // a clamped thread link: both its nodes, the link turning to the grip's direction
        const Vec3 direction = ((1.0 - f) * clampFrom_[g] + f * grip.direction.normalized()).normalized();
        current_[g].direction = direction;
        const std::array<Vec3, 2> ends = clampedLinkEnds(model, grip, current_[g].position, direction);
        leaders_.push_back({grip.node, ends[0]});
        leaders_.push_back({grip.node + 1, ends[1]});
      }
      if (onNeedle && needleGrip == nullptr) {
        needleGrip = &current_[g];
        if (grip.oriented)
          needlePose = needleFrom.slerp(f, Eigen::Quaterniond(grip.rotation)).toRotationMatrix();
      }
    }
    const bool needleHeld = needleGrip != nullptr;
    if (needleHeld) {
      // a held needle keeps its pose (or turns to the grip's): every needle node is posed from
      // the grip point, where the grip's node or its point between two nodes lies at rest
      const Points& r = model.needleShape();
      const int a = needleGrip->node;
      const double t = needleGrip->fraction;
      const Vec3 anchor = t == 0.0 ? Vec3(r.col(a)) : Vec3((1.0 - t) * r.col(a) + t * r.col(a + 1));
      for (int k = 0; k <= swage; ++k)
        if (k != a || t != 0.0) leaders_.push_back({k, needleGrip->position + needlePose * (r.col(k) - anchor)});
    }
    for (const Pierce& p : state.pierces)
      if (p.node >= swage && !yields(world, p)) leaders_.push_back({p.node, p.point});
    inNodeOrderOnce(leaders_);
    // the turns wound on a forceps' jaws stay where they are: a hole that slid moves the span
    // to the turns, not the turns (carried with the span from a grip beyond them, they were
    // thrown 0.1 mm in a step, some into the jaws, and the turns came undone)
    carried_ = leaders_;
    for (const Sleeve& sleeve : world.sleeves)
      for (const int node : {sleeve.first, sleeve.last})
        if (node >= 0 && node < nodes) carried_.push_back({node, state.x.col(node)});
    inNodeOrderOnce(carried_);
    carry(model, state.x, state.alive, carried_);

    // who contacts may move; pierced faces do not push the thread passing through them
    std::fill(movable_.begin(), movable_.end(), std::uint8_t{1});
    for (const Leader& l : leaders_) movable_[static_cast<std::size_t>(l.node)] = 0;
    movableSurface_ = movable_;
    for (int k = 0; k < std::min(swage, nodes); ++k) movableSurface_[static_cast<std::size_t>(k)] = 0;
    exemptions_.clear();
    for (const Pierce& p : state.pierces)
      exemptions_.push_back({std::max(0, p.node - 3), p.node + 3, p.face});

    for (int it = 0; it < params.iterations; ++it) {
      // contacts: the nodes they correct become soft leaders of this round; friction acts on
      // the substep's predicted motion only (later rounds would undo the length corrections)
      const double muNow = it == 0 ? mu : 0.0;
      std::fill(contact_.begin(), contact_.end(), std::uint8_t{0});
      for (const Leader& l : leaders_) state.x.col(l.node) = l.position;
      for (const Pierce& p : state.pierces)
        if (p.node >= swage && yields(world, p))
          state.x.col(p.node) += world.yieldShare * (p.point - state.x.col(p.node));
      report.contactNodes = projectCapsuleContacts(state.x, xStart_, world.capsules, radius, muNow,
                                                   movable_, contact_, &blocks_, state.alive);
      report.contactNodes +=
          projectSleeves(state.x, xStart_, world.sleeves, radius, muNow, movable_, contact_);
      if (world.surface)
        report.contactNodes += projectSurfaceContacts(state.x, xStart_, *world.surface, radius,
                                                      muNow, movableSurface_, exemptions_, contact_,
                                                      &blocks_);
      std::fill(selfTouched_.begin(), selfTouched_.end(), std::uint8_t{0});
      report.selfPairs = params.selfContact ? self_.project(state.x, xStart_, radius, muNow, selfSkip,
                                                            movable_, state.alive, &selfTouched_)
                                            : 0;
      if (params.selfContact) separated_ = state.x;

      // the bending limit on thread nodes nothing holds or touches
      for (std::size_t k = 0; k < free_.size(); ++k)
        free_[k] = movableSurface_[k] && !contact_[k] && !selfTouched_[k];
      limitBending(state.x, model.restLengths(), state.alive, free_, params.maxTurn);

      // lengths, then the rigid needle
      const bool restored =
          restoreLengths(model, state.x, state.alive, leaders_, contact_, params, it);
      const bool needleFree = model.needleLinks() > 0 && !needleHeld;
      if (needleFree) rigidifyNeedle(model, state.x, swage);
      // nothing touched and nothing left to reconcile: another round would change nothing
      if (report.contactNodes == 0 && report.selfPairs == 0 && restored && !needleFree) break;
    }

    // a last contact pass without friction (it would undo the length corrections): the substep
    // ends outside every obstacle, where the next one starts; the lengths it broke are restored
    // once more with the nodes it placed nearly held (finalContactWeight: they sink back by a
    // small share of the residual, far less than the thread's radius, instead of leaving the
    // whole residual as stretch on their links)
    std::fill(contact_.begin(), contact_.end(), std::uint8_t{0});
    int placed = projectCapsuleContacts(state.x, xStart_, world.capsules, radius, 0.0, movable_,
                                        contact_, &blocks_, state.alive);
    placed += projectSleeves(state.x, xStart_, world.sleeves, radius, 0.0, movable_, contact_);
    if (world.surface)
      placed += projectSurfaceContacts(state.x, xStart_, *world.surface, radius, 0.0,
                                       movableSurface_, exemptions_, contact_, &blocks_);
    if (placed > 0) {
      SutureStepParams hold = params;
      hold.contactWeight = params.finalContactWeight;
      restoreLengths(model, state.x, state.alive, leaders_, contact_, hold, params.iterations);
      if (model.needleLinks() > 0 && !needleHeld) rigidifyNeedle(model, state.x, swage);
    }

    // last, the thread against itself once more, without friction: the substep ends with no
    // two strands closer than the thread's diameter. Everything before it ends in a length
    // restore, which pulls strands wound round each other together when the thread is drawn
    // tight; with contact checked only before it, two strands of a knot crept into each other
    // (20 µm apart, then 18, 14, ..., 1) and crossed within 15 steps, so a surgeon's knot pulled
    // by both ends came apart into a square one. The lengths this pass disturbs are the
    // thread's stretch under the knot's tension, restored by the next substep; the links it
    // leaves past knotBreakStretch while the hands draw a knot on past tight are where the
    // thread breaks (knot_strain.h), the pressed nodes it marks say where. Its start is where
    // the last round's self-contact left the strands, parted (`separated_`): a pair the length
    // restore since has dragged through each other is put back on the side it came from. With
    // the strands' positions now as the start instead, a strand flicked across another at
    // 0.6 mm a frame (four substeps) was dragged through by that restore and this pass pushed it
    // on through. It moves neither the leaders nor the rigid needle. The paper's
    // follow-the-leader ("ftl") stays as it was, the faithful peer whose lengths are exact after
    // every substep.
    const bool selfPass = params.selfContact && name() != "ftl";
    std::fill(selfTouched_.begin(), selfTouched_.end(), std::uint8_t{0});
    if (selfPass)
      self_.project(state.x, separated_, radius, 0.0, selfSkip, movableSurface_, state.alive,
                    &selfTouched_);

    // slide through pierces, then break between grips, or in a knot drawn past tight
    state.time += h;
    holesBefore_.clear();
    for (const Pierce& p : state.pierces) holesBefore_.push_back(p.node);
    anchors_.clear();
    for (const Sleeve& sleeve : world.sleeves) anchors_.push_back({sleeve.first, sleeve.last});
    const int slid =
        slidePierces(model, state, current_, params.slideTolerance, report.events, anchors_);
    report.slides += slid;
    if (slid > 0 && name() != "ftl")
      relayFreeTails(model, state, holesBefore_, current_, selfTouched_);
    std::optional<int> link = findBreak(model, state, current_);
    if (!link && selfPass) link = findKnotBreak(model, state, current_, selfTouched_, selfSkip, h);
    if (link) {
      state.alive[static_cast<std::size_t>(*link)] = 0;
      report.events.push_back({SutureEventKind::Break, *link, -1, state.time});
    }
  }
  report.maxStretch = maxAbsStretch(model, state.x, state.alive);
  return report;
}

std::unique_ptr<SutureSolver> makeSutureSolver(std::string_view name) {
  if (name == "ftl") return std::make_unique<FollowTheLeaderSolver>();
  if (name == "direct") return std::make_unique<DirectSolver>();
  return nullptr;
}

std::vector<std::string> sutureSolverNames() { return {"ftl", "direct"}; }

}  // namespace microsim::sim::suture
