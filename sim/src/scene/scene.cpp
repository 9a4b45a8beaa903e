#include "microsim/sim/scene/scene.h"

#include "thread_jaw_obstacles.h"
#include "collide/stale_contact.h"

#include "microsim/sim/solve/state_hash.h"
#include "microsim/sim/suture/suture_coupling.h"
#include "microsim/sim/tools/jaw_contact.h"
#include "microsim/sim/tools/microscissors.h"
#include "microsim/sim/tools/scalpel.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <utility>

namespace microsim::sim {

namespace {

double steadySeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

Eigen::Isometry3d poseOf(const HandInput& h) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = h.orientation.normalized().toRotationMatrix();
  pose.translation() = h.position;
  return pose;
}

bool holdsJaws(Instrument i) { return i == Instrument::Forceps || i == Instrument::NeedleHolder; }

}  // namespace

// the tissue's collision trees, of the scene's volume type; each built only when needed
class SceneCollision {
 public:
  virtual ~SceneCollision() = default;
  virtual void maintain(const std::vector<int>& moved, const Points& x) = 0;
  virtual void crossings(const SpringModel& tissue, const Points& x, const Vec3& p, const Vec3& q,
                         std::vector<tools::FaceCrossing>& out) = 0;
  virtual void passedOver(const SpringModel& tissue, const Points& before, const Points& x, const Vec3& tip,
                          double reach, std::vector<tools::FaceCrossing>& out) = 0;
  virtual std::vector<int> cut(SpringModel& tissue, const Points& x, const ScalpelDef& def,
                               const Eigen::Isometry3d* from, const Eigen::Isometry3d& to) = 0;
};

namespace {

template <class Volume>
class TreeCollision final : public SceneCollision {
 public:
  TreeCollision(const SpringModel& tissue, const Points& x, bool faces, bool links) {
    if (faces && !tissue.triangles().empty()) pierce_.emplace(tissue, x);
    if (links && tissue.linkCount() > 0) cutter_.emplace(tissue, x);
  }
  void maintain(const std::vector<int>& moved, const Points& x) override {
    if (pierce_) pierce_->maintain(moved, x);
    if (cutter_) cutter_->maintain(moved, x);
  }
  void crossings(const SpringModel& tissue, const Points& x, const Vec3& p, const Vec3& q,
                 std::vector<tools::FaceCrossing>& out) override {
    out.clear();
    if (pierce_) pierce_->crossings(tissue, x, p, q, out);
  }
  void passedOver(const SpringModel& tissue, const Points& before, const Points& x, const Vec3& tip, double reach,
                  std::vector<tools::FaceCrossing>& out) override {
    out.clear();
    if (pierce_) pierce_->passedOver(tissue, before, x, tip, reach, out);
  }
  std::vector<int> cut(SpringModel& tissue, const Points& x, const ScalpelDef& def,
                       const Eigen::Isometry3d* from, const Eigen::Isometry3d& to) override {
    return cutter_ ? cutter_->cut(tissue, x, def, from, to) : std::vector<int>{};
  }

 private:
  std::optional<tools::PierceDetector<Volume>> pierce_;
  std::optional<tools::LinkCutter<Volume>> cutter_;
};

// the chain as the jaws meet it: the thread starts past the rigid needle (its nodes cannot
// wind), the same for the jaws' obstacles and for what they grasp
ThreadNearJaws threadNearJaws(const suture::SutureModel& model, const suture::SutureState& state,
                              int freeNeedleSwage) {
  const int firstThread = model.def().needleLinks > 0 ? model.swage() + 1 : 0;
  return {state.x, state.alive, freeNeedleSwage, firstThread, model.def().contactRadius};
}

}  // namespace

Scene::Scene(SceneDef def, StepMode mode, ClockFunction clock)
    : def_(std::move(def)), mode_(mode), clock_(clock ? std::move(clock) : ClockFunction(steadySeconds)) {
  SpringModel& tissue = def_.tissue.model;
  if (!tissue.finalized()) tissue.finalize();
  state_ = SpringState::atRest(tissue);
  solver_ = makeSolver(def_.solver.name, def_.solver.params);
  if (!solver_) solver_ = makeSolver("newton", def_.solver.params);

  // the needle and its suture, laid out at the declared pose
  if (def_.needle) {
    suture_.emplace(def_.needle->suture);
    suture_->gravity = tissue.gravity;
    sutureState_ = suture::SutureState::laidOut(*suture_, def_.needle->pose);
    if (def_.needle->initialShape.cols() == suture_->nodeCount()) {
      sutureState_.x = def_.needle->initialShape;
      sutureState_.xPrev = def_.needle->initialShape;
      // holes already made (a stay stitch): no PierceEvent stands for them
      sutureState_.pierces = def_.needle->initialPierces;
      suturePierceEvents_.assign(def_.needle->initialPierces.size(), -1);
    }
    knots_.emplace(def_.needle->knots);
    sutureSolver_ = suture::makeSutureSolver(def_.needle->solver);
    if (!sutureSolver_) sutureSolver_ = suture::makeSutureSolver("direct");
    if (!tissue.triangles().empty())
      surface_ = std::make_unique<suture::ContactSurface>(tissue.triangles(), state_.x);
  }
  for (int h = 0; h < kHandCount; ++h)
    if (def_.forceps[static_cast<std::size_t>(h)])
      forceps_[static_cast<std::size_t>(h)].emplace(*def_.forceps[static_cast<std::size_t>(h)]);

  // contact where the solver can take it
  const ContactDef& contact = def_.contact;
  if (solver_->supportsPointSprings() && (contact.tissue || contact.tools) && !tissue.triangles().empty())
    contact_.emplace(tissue, contact.params);

  // the tip dents a wall before it punctures it, where the solver takes soft terms: held to
  // the face as stiffly as contact holds faces apart
  if (def_.needle && def_.needle->punctureForce > 0.0 && solver_->supportsPointSprings())
    indentStiffness_ = contact_ ? contact_->stiffness() : collide::defaultContactStiffness(tissue);

  // trees only for the tools that need them
  const bool faces = def_.needle.has_value();
  const bool links = def_.scalpel.has_value();
  if (faces || links) {
    if (def_.tree == CollisionTree::Aabb)
      collision_ = std::make_unique<TreeCollision<collide::Aabb>>(tissue, state_.x, faces, links);
    else
      collision_ = std::make_unique<TreeCollision<collide::Sphere>>(tissue, state_.x, faces, links);
  }
}

Scene::~Scene() = default;

void Scene::addEvent(SceneEventKind kind, int hand, int index, int count) {
  SceneEvent e;
  e.kind = kind;
  e.time = time_;
  e.step = steps_;
  e.hand = hand;
  e.index = index;
  e.count = count;
  events_.push_back(e);
}

void Scene::placeTools(const InputFrame& frame) {
  for (int h = 0; h < kHandCount; ++h) {
    const std::size_t hs = static_cast<std::size_t>(h);
    const HandInput& in = frame.hands[hs];
    bladeWas_[hs] = blade_[hs];
    blade_[hs].reset();
    scissorsWas_[hs] = scissors_[hs];
    scissors_[hs].reset();
    auto& forceps = forceps_[hs];

    // a lost hand leaves its tool where it was
    if (!in.tracked) {
      if (forceps) grabDue_[hs] = false;
      if (in.instrument == Instrument::Scalpel) blade_[hs] = bladeWas_[hs];
      if (in.instrument == Instrument::Scissors) scissors_[hs] = scissorsWas_[hs];
      continue;
    }
    const Eigen::Isometry3d pose = poseOf(in);
    if (in.instrument == Instrument::Scalpel && def_.scalpel) blade_[hs] = pose;
    if (in.instrument == Instrument::Scissors && def_.scissors) scissors_[hs] = ScissorsPose{pose, in.closure};
    if (!forceps) continue;
    jawsPlaced_[hs] = holdsJaws(in.instrument);

    // jaws follow the hand; a hand that put the forceps down opens it
    const double closure = holdsJaws(in.instrument) ? in.closure : 0.0;
    bool released = false;
    grabDue_[hs] = forceps->update(pose, closure, dt(), released);
    if (released) {
      if (forceps->holdsSuture()) addEvent(SceneEventKind::ReleaseSuture, h, forceps->heldSutureNode(), 1);
      if (!forceps->heldNodes().empty())
        addEvent(SceneEventKind::ReleaseTissue, h, -1, static_cast<int>(forceps->heldNodes().size()));
      forceps->release();
    }
  }
}

BetweenJaws Scene::betweenJaws(Hand hand, double closure) const {
  const std::size_t hs = static_cast<std::size_t>(hand);
  BetweenJaws found;
  if (!forceps_[hs]) return found;
  const tools::Forceps& f = *forceps_[hs];

  // the suture first: the point of the needle or thread between the jaws nearest where they meet
  if (suture_) {
    // not the turns wound on these jaws: they lie round them, and the jaws close on the tail
    const ThreadNearJaws thread = threadNearJaws(*suture_, sutureState_, -1);
    std::vector<std::uint8_t> takeable = sutureState_.alive;
    for (const std::array<int, 2>& run : threadWoundOnJaws(f, thread))
      for (int link = std::max(run[0] - 1, 0);
           link <= run[1] && link < static_cast<int>(takeable.size()); ++link)
        takeable[static_cast<std::size_t>(link)] = 0;
    const tools::GraspRegion region = tools::graspRegion(f.def(), f.pose(), closure, suture_->def().contactRadius);
    found.suture = tools::chainPointBetweenJaws(region, sutureState_.x, takeable);
    if (found.suture) return found;
  }

  // then the tissue faces between the jaws (a needle holder does not take tissue), but not
  // those the other hand holds
  const bool holder = lastFrame_ && lastFrame_->hands[hs].instrument == Instrument::NeedleHolder;
  if (holder) return found;
  const SpringModel& tissue = def_.tissue.model;
  std::vector<std::uint8_t> skip(static_cast<std::size_t>(tissue.nodeCount()), 0);
  for (std::size_t h = 0; h < forceps_.size(); ++h)
    if (h != hs && forceps_[h])
      for (int n : forceps_[h]->heldNodes()) skip[static_cast<std::size_t>(n)] = 1;
  found.faces = tools::facesBetweenJaws(tools::graspRegion(f.def(), f.pose(), closure, 0.0), tissue, state_.x, skip);
  return found;
}

void Scene::grab(int hand) {
  tools::Forceps& f = *forceps_[static_cast<std::size_t>(hand)];
  const BetweenJaws found = betweenJaws(static_cast<Hand>(hand), f.closedFrom());
  if (found.suture) {
    f.holdSuture(*found.suture, *suture_, sutureState_.x);
    addEvent(SceneEventKind::GripSuture, hand, f.heldSutureNode(), 1);
    return;
  }
  if (found.faces.empty()) {
    addEvent(SceneEventKind::GraspEmpty, hand, -1, 0);
    return;
  }
  f.holdTissue(found.faces, def_.tissue.model, state_.x);
  addEvent(SceneEventKind::GrabTissue, hand, f.heldNodes().front(), static_cast<int>(f.heldNodes().size()));
}

void Scene::cutThread() {
  const suture::SutureModel& model = *suture_;
  std::vector<int> anchors;  // where the thread is held in the tissue
  for (int h = 0; h < kHandCount; ++h) {
    const std::size_t hs = static_cast<std::size_t>(h);
    // scissors picked up already closed do not cut: the closing must happen in the hand
    if (!scissors_[hs] || !scissorsWas_[hs]) continue;
    const std::vector<tools::ThreadCut> cuts =
        tools::scissorsCuts(*def_.scissors, scissors_[hs]->pose, scissorsWas_[hs]->closure, scissors_[hs]->closure,
                            sutureState_.x, sutureState_.alive, model.needleLinks(), model.def().contactRadius);
    if (cuts.empty()) continue;
    anchors.clear();
    for (const suture::Pierce& p : sutureState_.pierces) anchors.push_back(p.node);
    for (const tools::ThreadCut& cut : cuts) {
      const std::optional<double> tail = tools::cutEndLength(sutureState_.x, sutureState_.alive, cut, anchors);
      const bool needleSide = tools::onNeedlePiece(sutureState_.alive, model.swage(), cut.link);
      sutureState_.alive[static_cast<std::size_t>(cut.link)] = 0;
      addEvent(SceneEventKind::ThreadCut, h, cut.link, 1);
      events_.back().value = tail ? *tail : -1.0;
      const double left = tools::threadOnNeedle(sutureState_.x, sutureState_.alive, model.swage());
      if (needleSide && left < def_.needle->minTieLength) {
        addEvent(SceneEventKind::ThreadTooShort, h, cut.link, 0);
        events_.back().value = left;
      }
    }
  }
}

void Scene::stepSuture() {
  const SpringModel& tissue = def_.tissue.model;
  suture::readPiercePoints(tissue, state_.x, sutureState_);
  std::vector<suture::Grip> grips;
  for (const auto& f : forceps_)
    if (f)
      if (auto g = f->grip()) grips.push_back(*g);
  suture::SutureWorld world;
  if (surface_) {
    surface_->update(state_.x);
    world.surface = surface_.get();
  }
  // the jaws are solid to the thread, open or closed, unless they hold it, and leave clear what
  // lies between them (thread_jaw_obstacles.h): it is wound round them in the instrument tie.
  // A needle lying free (nothing holds the suture) is the one opened jaws reach round to take.
  const int freeNeedleSwage = suture_->def().needleLinks > 0 && grips.empty() ? suture_->swage() : -1;
  const ThreadNearJaws thread = threadNearJaws(*suture_, sutureState_, freeNeedleSwage);
  for (std::size_t h = 0; h < forceps_.size(); ++h) {
    const auto& f = forceps_[h];
    if (f && jawsPlaced_[h]) appendThreadJawObstacles(*f, thread, world);
  }
  // a knot tightened over the stitch: its holes give way to the thread (suture_solver.h)
  if (knotOverStitch_) world.yieldingBetween = {knotOverStitch_->first, knotOverStitch_->last};
  suture::SutureStepParams params = def_.needle->step;
  params.dt = dt();
  tipBefore_ = sutureState_.x.col(0);
  const suture::SutureStepReport report = sutureSolver_->step(*suture_, sutureState_, grips, world, params);
  tipAfter_ = sutureState_.x.col(0);
  tangentAfter_ = tools::needleTipTangent(*suture_, sutureState_.x);
  needleHeld_ = false;
  for (const suture::Grip& g : grips) needleHeld_ = needleHeld_ || suture::gripHoldsNeedle(*suture_, g);
  for (const suture::SutureEvent& e : report.events) {
    if (e.kind == suture::SutureEventKind::Break) {
      addEvent(SceneEventKind::SutureBreak, -1, e.link, 1);
      continue;
    }
    // a pierce left the suture: reported by the pierce it was made as
    const auto at = suturePierceEvents_.begin() + e.pierce;
    addEvent(e.kind == suture::SutureEventKind::Released ? SceneEventKind::PierceReleased
                                                         : SceneEventKind::SuturePulledOut,
             -1, *at, 1);
    suturePierceEvents_.erase(at);
  }
  // the holes that gave way lead the walls to where the thread left them (suture_coupling.h)
  if (world.yieldingBetween)
    for (suture::Pierce& p : sutureState_.pierces)
      if (p.node > (*world.yieldingBetween)[0] && p.node < (*world.yieldingBetween)[1])
        p.point = sutureState_.x.col(p.node);
  // two-way coupling where the tissue solver takes soft terms, by position otherwise
  if (solver_->supportsPointSprings())
    couplingSprings_ = suture::couplingSprings(tissue, state_.x, *suture_, sutureState_, grips,
                                               def_.needle->coupling, knotOverStitch_);
  else
    coupling_ = suture::couplingControls(tissue, state_.x, *suture_, sutureState_, grips,
                                         def_.needle->coupling, knotOverStitch_);
}

PierceEvent Scene::describePierce(const tools::FaceCrossing& c, const Vec3& tangent, const Vec3& aimed) const {
  PierceEvent e;
  e.time = time_;
  e.entry = c.entry;
  e.point = c.point;
  e.face = c.face;
  e.barycentric = c.barycentric;
  e.tangent = tangent;
  e.normal = c.normal;

  // measured on the undeformed tissue: the wall the trainee aimed at, not the dent
  const SpringModel& tissue = def_.tissue.model;
  const Points rest = tissue.restPositions();
  const auto& corners = tissue.triangles()[static_cast<std::size_t>(c.face)];
  for (std::size_t k = 0; k < 3; ++k) e.restPoint += c.barycentric[static_cast<Eigen::Index>(k)] * rest.col(corners[k]);
  const Vec3 restNormal = tools::faceNormal(tissue, rest, c.face);
  e.angleDeg = tools::pierceAngleDeg(aimed, restNormal.isZero(0.0) ? c.normal : restNormal);

  // which vessel, which surface, which wall, how far from the cut
  if (const auto on = vesselSurfaceOf(def_.vessels, c.face)) {
    const SceneVessel& vessel = def_.vessels[static_cast<std::size_t>(on->first)];
    e.vessel = on->first;
    e.end = vessel.end;
    e.surface = on->second;
    const Vec3 axis = vessel.def.direction;
    const Vec3 rel = e.restPoint - vessel.def.origin;
    const double along = rel.dot(axis);
    const Vec3 radial = rel - along * axis;
    e.wall = radial.dot(def_.camera.eye - e.restPoint) >= 0.0 ? VesselWall::Front : VesselWall::Back;
    e.biteMm = vessel.def.length - along;
  }
  return e;
}

double Scene::wallThickness(int face) const {
  const auto on = vesselSurfaceOf(def_.vessels, face);
  return on ? def_.vessels[static_cast<std::size_t>(on->first)].def.wallThickness : 0.0;
}

void Scene::applyCrossings() {
  // only a held needle is driven through tissue (a loose one has nothing to push it), and a
  // tip let go or drawn back stops pressing
  if (indent_ && (!needleHeld_ || tools::tipWithdrawn(def_.tissue.model, state_.x, *indent_, tipAfter_)))
    indent_.reset();
  if (!needleHeld_ || indent_) return;
  std::vector<tools::FaceCrossing> hits;
  collision_->crossings(def_.tissue.model, state_.x, tipBefore_, tipAfter_, hits);
  takeCrossings(hits, (tipAfter_ - tipBefore_).dot(tangentAfter_) > 0.0);
}

void Scene::takeCrossings(const std::vector<tools::FaceCrossing>& hits, bool cutting) {
  for (const tools::FaceCrossing& c : hits) {
    // the tip sat in a dent's apex when it punctured: going on, it may cross the dent's other
    // faces either way as they spring back, and that is the same passage
    if (std::find(punctured_.begin(), punctured_.end(), c.face) != punctured_.end()) continue;
    // nor can it go into the material it is in, or out of what it is not in: a face that
    // sprang back over a tip resting on it
    if (c.entry == tipInWall_) continue;
    punctured_.clear();

    // an entry the tip cuts dents the wall first, and the crossings behind it wait for the
    // puncture; a tip going back, tail first, follows the channel it cut
    if (c.entry && cutting && indentStiffness_ > 0.0) {
      indent_ = tools::beginIndentation(c, wallThickness(c.face));
      return;
    }
    // the needle's tangent where its body passes the crossing (tools/needle.h, Angles)
    const Vec3 tangent = tools::needleTangentNear(*suture_, sutureState_.x, c.point);
    pierceAt(c, tangent, tangent);
  }
}

void Scene::pierceAt(const tools::FaceCrossing& c, const Vec3& tangent, const Vec3& aimed) {
  pierces_.push_back(describePierce(c, tangent, aimed));
  addEvent(c.entry ? SceneEventKind::PierceEntry : SceneEventKind::PierceExit, -1,
           static_cast<int>(pierces_.size()) - 1, 1);

  // the suture runs through the wall here from now on
  suture::Pierce p;
  p.face = c.face;
  p.barycentric = c.barycentric;
  p.node = 0;
  p.point = c.point;
  sutureState_.pierces.push_back(p);
  suturePierceEvents_.push_back(static_cast<int>(pierces_.size()) - 1);
  tipInWall_ = c.entry;
}

void Scene::checkPuncture() {
  const SpringModel& tissue = def_.tissue.model;
  if (!indent_ || !tools::punctured(tissue, state_.x, *indent_, tipAfter_, tangentAfter_, indentStiffness_,
                                    def_.needle->punctureForce))
    return;

  // through: the pierce is where the face's point is now, under the tip; its angle is the
  // needle's where its body passes the point the tip first touched (the tip has turned on
  // along its curve since)
  tools::FaceCrossing c = indent_->touch;
  c.point = tools::indentedPoint(tissue, state_.x, *indent_);
  c.normal = tools::faceNormal(tissue, state_.x, c.face);
  const Vec3 aimed = tools::needleTangentNear(*suture_, sutureState_.x, indent_->touch.point);
  indent_.reset();
  pierceAt(c, tangentAfter_, aimed);
  punctured_ = tools::facesAround(tissue, c.face);
}

void Scene::assembleControls() {
  const SpringModel& tissue = def_.tissue.model;
  controls_ = SpringControls{};
  std::vector<std::uint8_t> taken(static_cast<std::size_t>(tissue.nodeCount()), 0);
  const auto add = [&](int node, const Vec3& target) {
    if (tissue.isFixed(node) || taken[static_cast<std::size_t>(node)]) return;
    taken[static_cast<std::size_t>(node)] = 1;
    controls_.add(node, target);
  };

  // forceps first (a hand wins; as point springs where the solver takes them), then the
  // scene's own controls, then the suture's pull
  std::vector<PointSpring> holds;
  for (const auto& f : forceps_) {
    if (!f || f->heldNodes().empty()) continue;
    if (solver_->supportsPointSprings()) {
      f->appendHoldSprings(holds);
      continue;
    }
    const Points targets = f->heldTargets();
    for (std::size_t k = 0; k < f->heldNodes().size(); ++k)
      add(f->heldNodes()[k], targets.col(static_cast<Eigen::Index>(k)));
  }
  const SpringControls& fixedControls = def_.tissue.controls;
  for (int c = 0; c < fixedControls.size(); ++c)
    add(fixedControls.nodes[static_cast<std::size_t>(c)], fixedControls.targets.col(c));
  for (int c = 0; c < coupling_.size(); ++c)
    add(coupling_.nodes[static_cast<std::size_t>(c)], coupling_.targets.col(c));
  controls_.springs = couplingSprings_;
  if (indent_) controls_.springs.push_back(tools::indentationSpring(tissue, *indent_, tipAfter_, indentStiffness_));
  controls_.springs.insert(controls_.springs.end(), holds.begin(), holds.end());
}

void Scene::checkStretch(const std::vector<int>& moved) {
  SpringModel& tissue = def_.tissue.model;
  const TissueLimitsDef& limits = def_.limits;
  if (overstretched_.size() != static_cast<std::size_t>(tissue.linkCount()))
    overstretched_.assign(static_cast<std::size_t>(tissue.linkCount()), 0);

  // the alive links of the nodes that moved, marked, then taken in index order (sorting them
  // took 0.08 ms a step, nearly all of the interactions stage, median over the stitch)
  linkMoved_.assign(static_cast<std::size_t>(tissue.linkCount()), 0);
  for (int i : moved)
    for (int li : tissue.linksOf(i))
      if (tissue.link(li).alive) linkMoved_[static_cast<std::size_t>(li)] = 1;

  // an event where an over-stretch starts; tears collected
  std::vector<int> torn;
  for (int li = 0; li < tissue.linkCount(); ++li) {
    if (!linkMoved_[static_cast<std::size_t>(li)]) continue;
    const Link& link = tissue.link(li);
    if (!(link.rest > 0.0)) continue;
    const double stretch = ((state_.x.col(link.b) - state_.x.col(link.a)).norm() - link.rest) / link.rest;
    std::uint8_t& over = overstretched_[static_cast<std::size_t>(li)];
    if (limits.overstretch > 0.0) {
      const bool now = stretch > limits.overstretch;
      if (now && !over)
        addEvent(SceneEventKind::TissueOverStretch, -1, li, static_cast<int>(std::lround(1000.0 * stretch)));
      over = now ? 1 : 0;
    }
    if (limits.tear > 0.0 && stretch > limits.tear) torn.push_back(li);
  }

  // tears are cuts: the links go, the solver's caches with them
  if (torn.empty()) return;
  for (int li : torn) {
    tissue.removeLink(li);
    overstretched_[static_cast<std::size_t>(li)] = 0;
  }
  addEvent(SceneEventKind::TissueTear, -1, torn.front(), static_cast<int>(torn.size()));
  solver_->reset();
}

namespace {
/// Tissue solves a step may take when the solves keep running into faces.
constexpr int kContactRounds = 3;
}  // namespace

std::vector<std::uint8_t> Scene::jawSkip() const {
  const SpringModel& tissue = def_.tissue.model;
  std::vector<std::uint8_t> skip(static_cast<std::size_t>(tissue.nodeCount()), 0);
  for (const auto& f : forceps_)
    if (f)
      for (int n : f->heldNodes()) skip[static_cast<std::size_t>(n)] = 1;
  return skip;
}

SolveReport Scene::solveTissue(const SolveBudget& budget, StepReport& report) {
  const SpringModel& tissue = def_.tissue.model;
  if (!contact_) {
    report.contactRounds = 1;
    return solver_->solve(tissue, state_, controls_, budget);
  }

  // contact terms from where the tissue is now: every node near a face it may touch, every
  // node near a placed jaw
  const std::size_t own = controls_.springs.size();
  std::vector<collide::TissueContactPair> pairs;
  std::vector<std::size_t> pairTerm;  // per pair, its term in controls_.springs
  if (def_.contact.tissue) {
    // the tissue has not moved since the last look (most steps of an attempt): same pairs
    if (nearX_.cols() != state_.x.cols() ||
        std::memcmp(nearX_.data(), state_.x.data(), sizeof(double) * static_cast<std::size_t>(state_.x.size())) != 0) {
      nearPairs_ = contact_->near(state_.x);
      nearX_ = state_.x;
    }
    pairs = nearPairs_;
    for (const auto& p : pairs) {
      pairTerm.push_back(controls_.springs.size());
      controls_.springs.push_back(contact_->spring(p, state_.x));
    }
  }
  // the jaws' terms last, so that a round can take them again from where the tissue went
  const std::vector<std::uint8_t> skip =
      def_.contact.tools ? jawSkip() : std::vector<std::uint8_t>{};
  const auto jawContacts = [&](std::vector<PointSpring>& out) {
    if (!def_.contact.tools) return;
    for (int h = 0; h < kHandCount; ++h) {
      const auto& f = forceps_[static_cast<std::size_t>(h)];
      if (f && jawsPlaced_[static_cast<std::size_t>(h)])
        tools::appendJawContacts(*f, tissue, state_.x, skip, def_.contact.params.reach,
                                 contact_->stiffness(), out);
    }
  };
  std::size_t jawsFrom = controls_.springs.size();
  jawContacts(controls_.springs);

  // solve; a node carried into a face it had no term for adds one (normal and contact point
  // taken from before the solve, when it was still outside), a term the face has swept away
  // from is dropped (collide/stale_contact.h), and the solve goes again. So it does when the
  // solve moved the faces a jaw presses on to where it meets other faces than those it had
  // terms for: a jaw's terms are taken where the faces were, and taken from one step to the
  // next they chase the wall round the jaw for several steps (an opened jaw resting on the
  // wall swung its stretch between 4 % and 17 % for ten steps before settling at 9 %).
  const Points before = state_.x;
  SolveReport total;
  std::vector<PointSpring> jaws;
  for (int round = 0; round < kContactRounds; ++round) {
    const SolveReport r = solver_->solve(tissue, state_, controls_, budget);
    total.status = r.status;
    total.residual = r.residual;
    total.iterations += r.iterations;
    total.seconds += r.seconds;
    report.contactRounds = round + 1;
    if (round + 1 == kContactRounds) break;
    if (std::memcmp(before.data(), state_.x.data(), sizeof(double) * static_cast<std::size_t>(before.size())) == 0)
      break;  // nothing moved, nothing ran into anything
    bool changed = false;
    jaws.clear();
    jawContacts(jaws);
    const bool jawFacesChanged = !std::equal(
        jaws.begin(), jaws.end(), controls_.springs.begin() + static_cast<std::ptrdiff_t>(jawsFrom),
        controls_.springs.end(),
        [](const PointSpring& a, const PointSpring& b) { return a.nodes == b.nodes; });
    if (jawFacesChanged) changed = true;
    const std::vector<PointSpring> solvedJaws(
        controls_.springs.begin() + static_cast<std::ptrdiff_t>(jawsFrom), controls_.springs.end());
    controls_.springs.resize(jawsFrom);
    if (def_.contact.tissue) {
      for (const std::size_t term : pairTerm) {
        PointSpring& sp = controls_.springs[term];
        if (!collide::contactIsStale(sp, state_.x, def_.contact.params.reach)) continue;
        sp.k = 0.0;  // let go, and kept in its place so that pairTerm stays true
        changed = true;
      }
      // (a dropped pair stays in `pairs`: it is not taken again as a violation this step)
      for (const auto& v : contact_->violations(state_.x)) {
        if (std::find(pairs.begin(), pairs.end(), v) != pairs.end()) continue;
        pairs.push_back(v);
        pairTerm.push_back(controls_.springs.size());
        controls_.springs.push_back(contact_->spring(v, before));
        changed = true;
      }
    }
    jawsFrom = controls_.springs.size();
    // the same faces: their terms kept as they were solved with
    const std::vector<PointSpring>& jawTerms = jawFacesChanged ? jaws : solvedJaws;
    controls_.springs.insert(controls_.springs.end(), jawTerms.begin(), jawTerms.end());
    if (!changed) break;
  }
  for (std::size_t k = own; k < controls_.springs.size(); ++k) {
    const PointSpring& sp = controls_.springs[k];
    if (!pointSpringForce(sp, pointSpringOffset(sp, state_.x)).isZero(0.0)) ++report.contacts;
  }
  return total;
}

StepReport Scene::step(const InputFrame& in) {
  const double start = now();
  StepReport report;
  const std::size_t eventsBefore = events_.size();
  time_ += dt();

  // input: a rejected frame is replaced by the last good one
  InputRejection why{};
  const double previous = lastFrame_ ? lastFrame_->time : -std::numeric_limits<double>::infinity();
  InputFrame frame = in;
  if (!validateSequence(in, previous, why)) {
    report.inputRejected = true;
    SceneEvent e;
    e.kind = SceneEventKind::InputRejected;
    e.time = time_;
    e.step = steps_;
    e.rejection = why;
    events_.push_back(e);
    frame = lastFrame_ ? *lastFrame_ : InputFrame{};
    for (HandInput& h : frame.hands) h.tracked = h.tracked && lastFrame_.has_value();
  }

  // interactions: tools placed, grabs taken
  double t0 = now();
  placeTools(frame);
  lastFrame_ = frame;
  for (int h = 0; h < kHandCount; ++h)
    if (grabDue_[static_cast<std::size_t>(h)]) grab(h);
  report.times.interactions += now() - t0;

  // suture: scissors cut it, then it steps
  t0 = now();
  if (suture_ && def_.scissors) cutThread();
  if (suture_) stepSuture();
  report.times.suture = now() - t0;

  // collision: trees refit where the tissue moved, then the needle's and the blade's tests
  t0 = now();
  std::vector<int> cutLinks;
  if (collision_) {
    if (suture_) applyCrossings();
    for (int h = 0; h < kHandCount; ++h) {
      const std::size_t hs = static_cast<std::size_t>(h);
      if (!blade_[hs]) continue;
      const Eigen::Isometry3d* from = bladeWas_[hs] ? &*bladeWas_[hs] : nullptr;
      std::vector<int> cut = collision_->cut(def_.tissue.model, state_.x, *def_.scalpel, from, *blade_[hs]);
      if (!cut.empty()) addEvent(SceneEventKind::Cut, h, cut.front(), static_cast<int>(cut.size()));
      cutLinks.insert(cutLinks.end(), cut.begin(), cut.end());
    }
  }
  report.times.collision = now() - t0;

  // interactions: cuts invalidate the solver's caches; the tissue's controls
  t0 = now();
  if (!cutLinks.empty()) solver_->reset();
  assembleControls();
  report.times.interactions += now() - t0;

  // tissue
  t0 = now();
  SolveBudget budget;
  budget.maxIterations = def_.solver.iterations;
  budget.residualTolerance = def_.solver.tolerance;
  if (mode_ == StepMode::RealTime) {
    budget.now = clock_;
    budget.since = start;
    budget.maxSeconds = def_.step.budgetMs * 1e-3;
  }
  const bool limited = def_.limits.overstretch > 0.0 || def_.limits.tear > 0.0;
  const Points before = collision_ || limited ? state_.x : Points(3, 0);
  report.tissue = solveTissue(budget, report);
  report.times.tissue = now() - t0;

  // collision: a tip pressing on a wall punctures it once it presses hard enough
  if (indent_) {
    t0 = now();
    checkPuncture();
    report.times.collision += now() - t0;
  }

  // the trees follow the nodes that moved (counted as collision time); their links are
  // checked against the stretch limits (interactions)
  if (collision_ || limited) {
    t0 = now();
    std::vector<int> moved;
    for (int i = 0; i < static_cast<int>(state_.x.cols()); ++i)
      if (state_.x.col(i) != before.col(i)) moved.push_back(i);
    if (collision_) collision_->maintain(moved, state_.x);
    if (suture_ && needleHeld_ && !indent_ && !moved.empty()) {
      // faces the solve carried over the standing tip
      double reach = 0.0;
      for (int i : moved) reach = std::max(reach, (state_.x.col(i) - before.col(i)).norm());
      std::vector<tools::FaceCrossing> hits;
      collision_->passedOver(def_.tissue.model, before, state_.x, tipAfter_, reach, hits);
      takeCrossings(hits, true);
    }
    report.times.collision += now() - t0;
    if (limited) {
      t0 = now();
      checkStretch(moved);
      report.times.interactions += now() - t0;
    }
  }

  // knots: the thread as the step left it
  if (knots_) {
    t0 = now();
    readKnots();
    report.times.suture += now() - t0;
  }

  ++steps_;
  report.events = static_cast<int>(events_.size() - eventsBefore);
  report.times.total = now() - start;
  return report;
}

std::uint64_t Scene::hash() const {
  std::uint64_t h = stateHash(state_);
  if (suture_) {
    const auto& s = sutureState_;
    h = fnv1a64(s.x.data(), sizeof(double) * static_cast<std::size_t>(s.x.size()), h);
    h = fnv1a64(s.xPrev.data(), sizeof(double) * static_cast<std::size_t>(s.xPrev.size()), h);
    h = fnv1a64(s.alive.data(), s.alive.size(), h);
    for (const suture::Pierce& p : s.pierces) {
      h = fnv1a64(&p.face, sizeof p.face, h);
      h = fnv1a64(&p.node, sizeof p.node, h);
      h = fnv1a64(p.barycentric.data(), sizeof(double) * 3, h);
    }
  }
  const std::uint8_t inWall = tipInWall_ ? 1 : 0;
  h = fnv1a64(&inWall, sizeof inWall, h);
  if (indent_) {
    h = fnv1a64(&indent_->touch.face, sizeof indent_->touch.face, h);
    h = fnv1a64(indent_->touch.barycentric.data(), sizeof(double) * 3, h);
  }
  for (const auto& f : forceps_) {
    if (!f) continue;
    const int node = f->heldSutureNode();
    const double fraction = f->heldSutureFraction();
    h = fnv1a64(&node, sizeof node, h);
    h = fnv1a64(&fraction, sizeof fraction, h);
    h = fnv1a64(f->heldNodes().data(), sizeof(int) * f->heldNodes().size(), h);
    for (const tools::HeldFacePoint& p : f->heldFaces()) {
      h = fnv1a64(&p.face, sizeof p.face, h);
      h = fnv1a64(p.barycentric.data(), sizeof(double) * 3, h);
    }
  }
  const std::int64_t alive = def_.tissue.model.aliveLinkCount();
  h = fnv1a64(&alive, sizeof alive, h);
  return fnv1a64(&steps_, sizeof steps_, h);
}

std::variant<std::unique_ptr<Scene>, SceneError> openScene(const std::string& path, StepMode mode) {
  SceneDefLoad load = loadSceneDef(path);
  if (auto* e = std::get_if<SceneError>(&load)) return *e;
  return std::make_unique<Scene>(std::move(std::get<SceneDef>(load)), mode);
}

}  // namespace microsim::sim
