#pragma once
// One step of the suture: the pipeline every thread solver shares, and the solvers.
//
// A step of dt is split into S substeps of h = dt/S (hand motion is interpolated across them,
// which with the continuous surface test keeps the thread from tunnelling at hand speeds).
// S adapts to the motion: the largest of the grips' moves this step, the needle grip's turn
// (times the needle's size) and the fastest node's velocity times dt, divided by
// maxSubstepMotion and rounded up, between 1 and `substeps`. A still or slow thread takes one
// substep; a hand at 10 mm/s (0.1 mm per 10 ms frame) five. The default, 0.02 mm, is the
// thread's contact diameter: with more per substep two strands pulled across each other can
// be pushed through by the length restore before the contact holds them.
// Each substep:
//   1. predict: x ← x + e^{−drag·h}(h/h_prev)(x − x_prev) + g h²   (Verlet; gravity from the model)
//   2. leaders: grips at their interpolated targets (a needle grip poses every needle node
//      from its point, a grip between two thread nodes places both along its direction:
//      suture_constraints.h), active pierces at their points (but for holes that give way to
//      the thread: SutureWorld::yieldingBetween); the solver may carry the chain with them
//      first (direct: carrySpans, chain_projection.h);
//   3. up to `iterations` rounds of: contacts (capsules, surface, self; contact nodes become
//      soft leaders, the paper's drape constraints) → the bending limit on free thread nodes
//      (bending_limit.h) → restore link lengths (the solver) → rigid needle; a round whose contacts
//      corrected nothing and whose lengths were restored ends the loop (the next would restore the
//      same lengths again);
//   4. a last frictionless contact pass (the substep ends outside every obstacle), and the
//      lengths it disturbed restored with its nodes nearly held (finalContactWeight);
//   5. sliding through pierces, then the break test between grips (suture_constraints.h).
// Velocity is carried implicitly by x_prev (position-based dynamics), so corrections damp
// themselves instead of injecting energy. Buffers live in the solver: a step allocates nothing
// once the chain's size is known (slides and breaks excepted).
//
// Solvers (makeSutureSolver):
//   "ftl"    — the paper, faithful: follow-the-leader from every leader, the two passes
//              averaged between leaders (follow_the_leader.h). Stretches between leaders.
//   "direct" — spans carried with their leaders (carrySpans), then exact lengths by the
//              tridiagonal Gauss–Newton projection (chain_projection.h), O(N) per sweep: no
//              stretch wherever the constraints allow it. Follow-the-leader outward of the
//              outermost leaders is only the fallback predictor when the projection does not
//              converge from the predicted chain: as the first predictor it whips a free tail
//              (its one-sided corrections, kept as Verlet velocity, add energy). (Averaging the two
//              passes, the paper's rule, is a poor predictor for a long span: its junction links
//              can start several times their length, and the projection then needs its damped
//              steps.)
//
// Units: millimetres, seconds, grams.

#include "microsim/sim/suture/bending_limit.h"
#include "microsim/sim/suture/chain_projection.h"
#include "microsim/sim/suture/follow_the_leader.h"
#include "microsim/sim/suture/suture_constraints.h"
#include "microsim/sim/suture/suture_contact.h"
#include "microsim/sim/suture/suture_model.h"

#include <array>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace microsim::sim::suture {

/// Of the way back to its point a hole that gives way to the thread is drawn each round. A
/// knot over the stitch (suture_coupling.h) pulls its holes; held as leaders, the hands' reach
/// in a frame went into the knot's few links (10 % over, and the knot broke) before the walls
/// could follow through the coupling. Drawn back a tenth of the way each round, the holes take
/// the reach instead (their nodes lead the wall by under 0.01 mm), and the walls follow: a
/// throw snugged 0.4 mm a hand at 0.1 mm/s closes lesson 2b's gap from 0.50 to 0.05 mm and
/// holds it. On the lesson's earlier, stiffer 3 mm vessel: 0.22 mm with 0.1 and 0.2, the knot
/// broken at 0.24 mm with 0.3 (README, "Session 26").
inline constexpr double kHoleYieldShare = 0.1;

/// The obstacles the suture meets this step (not owned).
struct SutureWorld {
  std::vector<Capsule> capsules;           ///< forceps jaws, needle holders
  std::vector<Sleeve> sleeves;             ///< turns wound on forceps jaws, kept there
  const ContactSurface* surface = nullptr; ///< the vessel or any supporting surface
  /// Holes that give way to the thread: active pierces whose nodes lie strictly between these
  /// two curve parameters (a knot over the stitch, suture_coupling.h). They are not leaders;
  /// each round their nodes are drawn `yieldShare` of the way back to their points.
  std::optional<std::array<double, 2>> yieldingBetween;
  double yieldShare = kHoleYieldShare;
};

struct SutureStepParams {
  double dt = 0.01;                   ///< s: one tracker frame
  int substeps = 8;                   ///< the most substeps per step, ≥ 1
  double maxSubstepMotion = 0.02;    ///< mm: motion per substep that adds one (0: always `substeps`)
  int iterations = 2;                 ///< the most contact ↔ length rounds per substep, ≥ 1
  bool selfContact = true;
  double slideTolerance = 1e-3;       ///< side stretch beyond 1 that makes a pierce slide
  int projectionIterations = 32;      ///< direct: max Gauss–Newton sweeps per round (stops at tolerance)
  double projectionTolerance = 1e-10; ///< direct: relative length residual to stop at
  double contactWeight = 0.25;        ///< direct: inverse-mass scale of nodes in contact
  double finalContactWeight = 0.02;   ///< direct: the same in the restore after the last contact pass
  double maxTurn = kDefaultMaxTurn;   ///< rad: sharpest turn between free links (bending_limit.h); ≥ π: off
};

enum class SutureStepStatus : std::uint8_t {
  Ok,
  InvalidInput,  ///< NaN/Inf or bad node indices in the grips or the state; nothing changed
};

struct SutureStepReport {
  SutureStepStatus status = SutureStepStatus::Ok;
  std::vector<SutureEvent> events;  ///< breaks and pull-outs, in the order they happened
  int slides = 0;                   ///< one-node slides through pierces
  int contactNodes = 0;             ///< nodes corrected by contacts in the last round
  int selfPairs = 0;                ///< link pairs corrected by self-contact in the last round
  double maxStretch = 0.0;          ///< max |relative stretch| over intact links at the end
  int substeps = 0;                 ///< substeps this step took
};

class SutureSolver {
 public:
  virtual ~SutureSolver() = default;
  virtual std::string_view name() const = 0;

  /// Advances `state` by params.dt with the grips held (hard constraints).
  SutureStepReport step(const SutureModel& model, SutureState& state, std::span<const Grip> grips,
                        const SutureWorld& world, const SutureStepParams& params = {});

 protected:
  /// Moves the predicted chain with its leaders before they are set (sorted by node, unique;
  /// x still holds the leader nodes' predicted positions). Default: nothing.
  virtual void carry(const SutureModel& model, Points& x, const std::vector<std::uint8_t>& alive,
                     std::span<const Leader> leaders);
  /// Restores link lengths; `leaders` are sorted by node and unique; `contact[i]` marks nodes
  /// corrected by contacts in this round. `round` counts this substep's rounds from 0. Returns
  /// false when the lengths are not restored to the solver's tolerance (another round helps).
  virtual bool restoreLengths(const SutureModel& model, Points& x,
                              const std::vector<std::uint8_t>& alive,
                              std::span<const Leader> leaders,
                              const std::vector<std::uint8_t>& contact,
                              const SutureStepParams& params, int round) = 0;

 private:
  int substepCount(const SutureModel& model, const SutureState& state, std::span<const Grip> grips,
                   const SutureStepParams& params) const;

  SelfContact self_;
  ChainBlocks blocks_;
  Points xStart_{3, 0};
  std::vector<Leader> leaders_;
  std::vector<Leader> carried_;   ///< the leaders and the ends of wound turns, for carry
  std::vector<int> holesBefore_;  ///< each pierce's node before this substep's slides
  std::vector<std::array<int, 2>> anchors_;  ///< the sleeves' runs, for slidePierces
  std::vector<Vec3> gripFrom_;
  std::vector<Vec3> clampFrom_;  // per grip between thread nodes: the link's direction at the step's start
  std::vector<Grip> current_;
  std::vector<std::uint8_t> movable_, movableSurface_, contact_, selfTouched_, free_;
  Points separated_{3, 0};  ///< the thread as the last round's self-contact left it, parted
  std::vector<ContactExemption> exemptions_;
};

/// The solver registered under `name` ("ftl", "direct"), or nullptr.
std::unique_ptr<SutureSolver> makeSutureSolver(std::string_view name);
/// Every name makeSutureSolver accepts, paper-faithful first.
std::vector<std::string> sutureSolverNames();

}  // namespace microsim::sim::suture
