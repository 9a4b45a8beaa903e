#pragma once
// The microsurgery scene at run time: the tissue, the needle and suture, the tools, and the
// fixed-rate step that ties them together (DESIGN.md §Data flow of one frame).
//
// One step of dt = 1/rate consumes one InputFrame, in four timed stages:
//   interactions  place the tools from the frame; a forceps that closes takes what lies
//                 between its jaws (tools/jaw_grasp.h): the needle or thread anywhere along
//                 it (a grip, hard), else the tissue faces there (barycentric points held
//                 by point springs, or their corners as control nodes where the solver takes
//                 no springs), else nothing, which is an event (GraspEmpty); one that opens
//                 lets go; then (after collision) new pierces become soft constraints of the
//                 suture, cut links are removed, and the tissue's controls are assembled
//                 (scene controls, held faces, the suture's pull);
//   suture        pierce points re-read from the tissue, the suture steps with the grips
//                 (the needle moves with the hand holding it), the coupling pull is computed;
//   collision     the needle tip's path this step is tested against the tissue faces
//                 (pierce entry and exit; only while a forceps holds the needle: nothing
//                 drives a loose needle through a wall; with a puncture force, an entry
//                 first dents the wall under the tip and pierces only when the tip presses
//                 hard enough or has carried the wall its thickness, checked after the
//                 tissue solve: tools/needle_indent.h), a
//                 scalpel's blade against the links; after the tissue solve the trees are
//                 refit where nodes moved;
//   tissue        the tissue solver runs with those controls and, where it takes soft
//                 terms, with contact: tissue against tissue and the placed forceps' jaws
//                 against tissue (one-sided springs detected before the solve; a node the
//                 solve carried into a face adds its term and the solve repeats, at most
//                 kContactRounds times); then the links of the nodes that moved are checked
//                 against the stretch limits (SceneDef::limits: over-stretch events, tears
//                 removed like cuts), counted as interactions.
// Last, with a suture, the thread as the step left it is read for a knot (suture/knot_tracker.h,
// counted as suture time): throws formed, a knot tightened or slipped become events; a thread
// that has not moved is not read again.
// Only what the scene declares is built: no needle, no face tree and no suture stage; no
// scalpel, no link tree.
//
// Determinism. In StepMode::Deterministic the tissue solve stops on the scene's iteration
// limit and tolerance only, never on the clock, so the same scene and the same frames give
// bit-identical states (hash()) on every run and build. StepMode::RealTime adds the wall-clock
// budget: the tissue solve gets what the step budget leaves after the other stages (its
// deadline is the step's start plus StepDef::budgetMs, on the scene's clock), and the solver
// checks that clock between iterations, so a step's tissue solve stops at its first check
// after the deadline: it overruns by at most one tissue iteration (plus any stage that alone
// exceeds the budget).
//
// The clock. Stage times and the budget are read from one clock, the steady wall clock
// unless the constructor is given another (a thread-CPU clock for benchmarks on a shared
// machine, a fake one for tests).
//
// Rejected input (NaN, non-unit rotation, closure out of range, time going backwards) never
// reaches the tools: the previous accepted frame is used again and an InputRejected event
// says why.
//
// Units: millimetres, seconds, grams.

#include "microsim/sim/collide/tissue_contact.h"
#include "microsim/sim/scene/input_frame.h"
#include "microsim/sim/scene/scene_def.h"
#include "microsim/sim/scene/scene_events.h"
#include "microsim/sim/solve/solver.h"
#include "microsim/sim/suture/knot_tracker.h"
#include "microsim/sim/suture/suture_model.h"
#include "microsim/sim/suture/suture_solver.h"
#include "microsim/sim/tools/forceps.h"
#include "microsim/sim/tools/needle.h"
#include "microsim/sim/tools/needle_indent.h"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace microsim::sim {

/// Time of one step's stages (s) on the scene's clock. Reported, never used by the simulation
/// in deterministic mode.
struct StageTimes {
  double interactions = 0.0;
  double suture = 0.0;
  double collision = 0.0;
  double tissue = 0.0;
  double total = 0.0;
};

enum class StepMode : std::uint8_t { Deterministic, RealTime };

struct StepReport {
  StageTimes times;
  SolveReport tissue;
  bool inputRejected = false;
  int events = 0;  ///< events this step added
  int contacts = 0;  ///< contact terms pressed at the end of the tissue solve
  int contactRounds = 0;  ///< tissue solves this step (more than one when a solve ran into a face)
};

class SceneCollision;

/// What lies between a forceps' jaws as a grab searches it (tools/jaw_grasp.h): the point of
/// the needle or thread the jaws would take, else the tissue faces they would hold.
struct BetweenJaws {
  std::optional<tools::ChainGrasp> suture;  ///< a link of the suture (needle links first)
  std::vector<tools::FaceGrasp> faces;      ///< empty when the suture is found (it is taken first)
};

class Scene {
 public:
  /// `clock`: seconds from any fixed origin, never decreasing; empty = the steady wall clock.
  explicit Scene(SceneDef def, StepMode mode = StepMode::Deterministic, ClockFunction clock = {});
  ~Scene();
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;

  /// Advances one fixed step of dt with this frame's hands.
  StepReport step(const InputFrame& frame);

  double dt() const { return 1.0 / def_.step.rateHz; }
  double time() const { return time_; }
  int steps() const { return steps_; }
  const SceneDef& def() const { return def_; }

  const SpringModel& tissue() const { return def_.tissue.model; }
  const SpringState& tissueState() const { return state_; }
  /// The suture and its state; null without a needle.
  const suture::SutureModel* sutureModel() const { return suture_ ? &*suture_ : nullptr; }
  const suture::SutureState* sutureState() const { return suture_ ? &sutureState_ : nullptr; }
  /// The forceps of a hand; null when the scene declares none for it.
  const tools::Forceps* forceps(Hand hand) const {
    const auto& f = forceps_[static_cast<std::size_t>(hand)];
    return f ? &*f : nullptr;
  }
  /// Where a hand's microscissors are and how closed, while it holds them (the scene
  /// declares scissors and the hand is tracked or was last seen holding them); none otherwise.
  struct ScissorsPose {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    double closure = 0.0;
  };
  const std::optional<ScissorsPose>& scissors(Hand hand) const {
    return scissors_[static_cast<std::size_t>(hand)];
  }
  /// What the jaws of `hand`'s forceps would close on closing from `closure` (0 open .. 1
  /// closed) at their pose now: the search a grab makes (the suture first, then the tissue
  /// faces not held by the other hand; a needle holder takes no tissue). Empty without a
  /// forceps. The viewport's contact cue asks it with the closure the jaws have now.
  BetweenJaws betweenJaws(Hand hand, double closure) const;
  /// The instrument `hand` held in the last frame stepped (InputFrame's default, the forceps,
  /// before the first).
  Instrument instrument(Hand hand) const {
    return lastFrame_ ? lastFrame_->hand(hand).instrument : HandInput{}.instrument;
  }
  /// The scalpel's pose (blade frame → scene) while `hand` holds it; none otherwise.
  const std::optional<Eigen::Isometry3d>& blade(Hand hand) const {
    return blade_[static_cast<std::size_t>(hand)];
  }
  /// The controls the last tissue solve had.
  const SpringControls& controls() const { return controls_; }

  /// The knot read from the thread after the last step; null without a suture.
  const suture::KnotTracker* knots() const { return knots_ ? &*knots_ : nullptr; }

  const std::vector<SceneEvent>& events() const { return events_; }
  const std::vector<PierceEvent>& pierces() const { return pierces_; }

  /// Golden-state hash: tissue positions and velocities, the suture's positions, previous
  /// positions, links and pierces, what every forceps holds (the suture node and the fraction
  /// along its link, the held nodes, each held face and its barycentric point), and the step
  /// count.
  std::uint64_t hash() const;

 private:
  void placeTools(const InputFrame& frame);
  void grab(int hand);
  void stepSuture();
  /// Microscissors closing this step cut the thread (tools/microscissors.h).
  void cutThread();
  void applyCrossings();
  /// `cutting`: the tip moves point first (a tip going back follows its channel: no dent)
  void takeCrossings(const std::vector<tools::FaceCrossing>& hits, bool cutting);
  /// `tangent`: the needle's where it passes the hole now (PierceEvent::tangent); `aimed`:
  /// where it passed the wall as the trainee met it, which the angle is read from
  void pierceAt(const tools::FaceCrossing& c, const Vec3& tangent, const Vec3& aimed);
  void checkPuncture();
  /// mm: the thickness of the vessel wall `face` belongs to; 0 for other tissue
  double wallThickness(int face) const;
  void assembleControls();
  void checkStretch(const std::vector<int>& moved);
  SolveReport solveTissue(const SolveBudget& budget, StepReport& report);
  std::vector<std::uint8_t> jawSkip() const;
  PierceEvent describePierce(const tools::FaceCrossing& c, const Vec3& tangent, const Vec3& aimed) const;
  void addEvent(SceneEventKind kind, int hand, int index, int count);
  /// The knot tracker reads the thread as the step left it (scene_knots.cpp).
  void readKnots();

  double now() const { return clock_(); }

  SceneDef def_;
  StepMode mode_;
  ClockFunction clock_;
  SpringState state_;
  std::unique_ptr<TissueSolver> solver_;
  SpringControls controls_;

  std::optional<suture::SutureModel> suture_;
  suture::SutureState sutureState_;
  std::unique_ptr<suture::SutureSolver> sutureSolver_;
  std::unique_ptr<suture::ContactSurface> surface_;
  std::optional<suture::KnotTracker> knots_;  ///< with the suture
  Points knotNodes_{3, 0};                    ///< the piece read, when the thread is cut
  std::vector<int> knotAnchors_;              ///< its pierced nodes, in the piece's numbering
  std::vector<double> knotStretch_;           ///< its links' stretch
  /// the knot tightened over the stitch, while it holds: it carries the hands' pull to the
  /// holes (suture_coupling.h)
  std::optional<suture::KnotOverStitch> knotOverStitch_;
  Vec3 tipBefore_ = Vec3::Zero();
  Vec3 tipAfter_ = Vec3::Zero();
  Vec3 tangentAfter_ = Vec3::UnitX();
  bool needleHeld_ = false;
  SpringControls coupling_;                  ///< the suture's pull by position
  std::vector<PointSpring> couplingSprings_;  ///< or as springs (two-way)
  std::optional<tools::Indentation> indent_;  ///< the tip pressing on a wall, not yet through
  double indentStiffness_ = 0.0;              ///< g/s²; 0 = crossings pierce at once
  std::vector<int> punctured_;                ///< the faces of the last dent, until the next crossing
  bool tipInWall_ = false;                    ///< the tip's last pierce was an entry

  std::array<std::optional<tools::Forceps>, kHandCount> forceps_;
  std::array<bool, kHandCount> jawsPlaced_{};  ///< a tracked hand holds the forceps: its jaws touch
  std::optional<collide::TissueContact> contact_;
  Points nearX_{3, 0};                               ///< the tissue when nearPairs_ were found
  std::vector<collide::TissueContactPair> nearPairs_;
  std::array<bool, kHandCount> grabDue_{};
  std::array<std::optional<Eigen::Isometry3d>, kHandCount> blade_;     // this step
  std::array<std::optional<Eigen::Isometry3d>, kHandCount> bladeWas_;  // last step
  std::array<std::optional<ScissorsPose>, kHandCount> scissors_;     // this step
  std::array<std::optional<ScissorsPose>, kHandCount> scissorsWas_;  // last step
  std::unique_ptr<SceneCollision> collision_;

  std::vector<std::uint8_t> overstretched_;  ///< per link: above the limit at the last check
  std::vector<std::uint8_t> linkMoved_;      ///< per link: an end moved this step (checkStretch)

  std::optional<InputFrame> lastFrame_;
  double time_ = 0.0;
  int steps_ = 0;
  std::vector<SceneEvent> events_;
  std::vector<PierceEvent> pierces_;
  /// per pierce the suture still passes through (SutureState::pierces order): its index into
  /// pierces_, which keeps every pierce made
  std::vector<int> suturePierceEvents_;
};

/// Loads a scene file and builds it; the error is the loader's.
std::variant<std::unique_ptr<Scene>, SceneError> openScene(const std::string& path,
                                                           StepMode mode = StepMode::Deterministic);

}  // namespace microsim::sim
