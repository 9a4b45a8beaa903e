#pragma once
// The tissue solvers' common interface. Every solver takes the constant model, the
// state it advances and this step's controls, and stops on whichever of its budget's
// limits comes first. Solvers are objects because they keep caches between steps
// (the paper's NODE-ORDERING, factorisations, warm starts); the model and state they
// are handed are the only truth.

#include "microsim/sim/mesh/spring_model.h"

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace microsim::sim {

/// The clock a time budget is measured on.
enum class BudgetClock : std::uint8_t {
  Wall,       ///< elapsed real time: what a frame deadline means
  ThreadCpu,  ///< CPU time of the calling thread: what benchmarks use, so that other load on
              ///< the machine does not change the figure (equal to Wall on an idle core)
};

/// A clock for time budgets: seconds (s) from any fixed origin, never decreasing.
using ClockFunction = std::function<double()>;

/// When a solve stops. Whichever limit is reached first ends it.
///
/// The time limit. Every solver reads its clock once when it starts, once before each
/// iteration (the check: it stops with TimeLimit when now − since ≥ maxSeconds), and once at
/// the end (SolveReport::seconds = end − start); it never reads it inside an iteration. So a
/// solve overruns its limit by at most one iteration. (qss checks before a sweep once 256
/// node updates have passed since its last check: for the rule, sweeps cut short by the
/// cutout count together up to that many updates.)
struct SolveBudget {
  int maxIterations = std::numeric_limits<int>::max();
  double maxSeconds = std::numeric_limits<double>::infinity();  ///< s on the clock below
  double residualTolerance = 0.0;  ///< stop once the relative residual is below this
  BudgetClock clock = BudgetClock::Wall;  ///< what maxSeconds and SolveReport::seconds measure
  /// When set, the clock instead of `clock`: a scene shares its step's clock with the solve,
  /// and tests run solvers on a fake one.
  ClockFunction now;
  /// The reading of the clock maxSeconds counts from (s); NaN: the solve's own start.
  double since = std::numeric_limits<double>::quiet_NaN();
};

enum class SolveStatus : std::uint8_t {
  Converged,       ///< relative residual ≤ tolerance
  IterationLimit,  ///< ran its iterations
  TimeLimit,       ///< ran out of time
  Diverged,        ///< the residual grew without bound; the state was restored to its input
  InvalidInput,    ///< NaN/Inf in the state or controls, bad indices; nothing was changed
};

struct SolveReport {
  SolveStatus status = SolveStatus::IterationLimit;
  int iterations = 0;
  double seconds = 0.0;
  double residual = 0.0;  ///< relative residual at the end (see relativeResidual)
};

/// Tunables shared by the solvers; each solver reads the ones it has.
struct SolverParams {
  double timeStep = 1.0 / 30.0;  ///< s: one cycle of the paper's simulation (rk4, implicit)
  double alpha = 0.0;            ///< qss step scale (mm per force unit); 0 = chosen from the model
  double relaxation = 1.0;       ///< qss: ω in the per-node α_i = ω / Σ_j T'_ij (alpha = 0), in (0, 2)
  double cutout = 0.0;           ///< qss per-level cutout ε (mm); 0 = off
  double momentum = 0.0;         ///< qss momentum β in [0, 1) (the paper's "CG-style" variant)
  double damping = 0.0;          ///< g/s: added to every node's own damping (rk4, implicit)
  bool activeRegion = true;      ///< newton: solve only where the pull reaches (see newton)
  double linearTolerance = 0.0;  ///< newton, implicit: PCG relative tolerance; 0 = automatic
};

class TissueSolver {
 public:
  virtual ~TissueSolver() = default;
  virtual std::string_view name() const = 0;
  virtual SolveReport solve(const SpringModel& model, SpringState& state,
                            const SpringControls& controls, const SolveBudget& budget) = 0;
  /// Forget caches (orderings, warm starts): call after topology or control-set changes
  /// that the solver cannot see for itself.
  virtual void reset() {}
  /// Whether the solver honours SpringControls::springs (point_spring.h); one that does not
  /// leaves them out of its forces, and the scene then couples by position (scene.h).
  virtual bool supportsPointSprings() const { return false; }
};

/// The solver registered under `name` ("qss", "rk4", "implicit", "newton", "reference"),
/// or nullptr for an unknown name.
std::unique_ptr<TissueSolver> makeSolver(std::string_view name, const SolverParams& params = {});
/// Every name makeSolver accepts, in a stable order.
std::vector<std::string> solverNames();

}  // namespace microsim::sim
