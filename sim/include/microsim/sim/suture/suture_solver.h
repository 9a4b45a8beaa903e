#pragma once
// One step of the suture: the pipeline every thread solver shares, and the solvers.
//
// A step of dt is split into substeps of h = dt/S (hand motion is interpolated across them,
// which with the continuous surface test keeps the thread from tunnelling at hand speeds).
// Each substep:
//   1. predict: x ← x + e^{−drag·h}(x − x_prev) + g h²   (Verlet; gravity from the model)
//   2. leaders: grips at their interpolated targets (an oriented needle grip poses every
//      needle node), active pierces at their points;
//   3. `iterations` rounds of: contacts (capsules, surface, self; contact nodes become soft
//      leaders, the paper's drape constraints) → restore link lengths (the solver) → rigid
//      needle;
//   4. sliding through pierces, then the break test between grips (suture_constraints.h).
// Velocity is carried implicitly by x_prev (position-based dynamics), so corrections damp
// themselves instead of injecting energy.
//
// Solvers (makeSutureSolver):
//   "ftl"    — the paper, faithful: follow-the-leader from every leader, the two passes
//              averaged between leaders (follow_the_leader.h). Stretches between leaders.
//   "direct" — follow-the-leader as a predictor, then exact lengths by the tridiagonal
//              Gauss–Newton projection (chain_projection.h), O(N) per sweep: no stretch
//              wherever the constraints allow it.
//
// Units: millimetres, seconds, grams.

#include "microsim/sim/suture/chain_projection.h"
#include "microsim/sim/suture/follow_the_leader.h"
#include "microsim/sim/suture/suture_constraints.h"
#include "microsim/sim/suture/suture_contact.h"
#include "microsim/sim/suture/suture_model.h"

#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace microsim::sim::suture {

/// The obstacles the suture meets this step (not owned).
struct SutureWorld {
  std::vector<Capsule> capsules;           ///< forceps jaws, needle holders
  const ContactSurface* surface = nullptr; ///< the vessel or any supporting surface
};

struct SutureStepParams {
  double dt = 0.01;                   ///< s: one tracker frame
  int substeps = 4;                   ///< S ≥ 1
  int iterations = 2;                 ///< contact ↔ length rounds per substep, ≥ 1
  bool selfContact = true;
  double slideTolerance = 1e-3;       ///< side stretch beyond 1 that makes a pierce slide
  int projectionIterations = 32;      ///< direct: max Gauss–Newton sweeps per round (stops at tolerance)
  double projectionTolerance = 1e-12; ///< direct: relative length residual to stop at
  double contactWeight = 0.25;        ///< direct: inverse-mass scale of nodes in contact
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
};

class SutureSolver {
 public:
  virtual ~SutureSolver() = default;
  virtual std::string_view name() const = 0;

  /// Advances `state` by params.dt with the grips held (hard constraints).
  SutureStepReport step(const SutureModel& model, SutureState& state, std::span<const Grip> grips,
                        const SutureWorld& world, const SutureStepParams& params = {});

 protected:
  /// Restores link lengths; `leaders` are sorted by node and unique; `contact[i]` marks nodes
  /// corrected by contacts in this round.
  virtual void restoreLengths(const SutureModel& model, Points& x,
                              const std::vector<std::uint8_t>& alive,
                              std::span<const Leader> leaders,
                              const std::vector<std::uint8_t>& contact,
                              const SutureStepParams& params) = 0;

 private:
  SelfContact self_;
  Points xStart_{3, 0};
  std::vector<Leader> leaders_;
};

/// The solver registered under `name` ("ftl", "direct"), or nullptr.
std::unique_ptr<SutureSolver> makeSutureSolver(std::string_view name);
/// Every name makeSutureSolver accepts, paper-faithful first.
std::vector<std::string> sutureSolverNames();

}  // namespace microsim::sim::suture
