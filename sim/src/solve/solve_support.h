#pragma once
// What every solver does around its iterations: reject bad input without touching the
// state, impose the controls, watch the clock, and decide divergence.

#include "microsim/sim/solve/solver.h"

#include <chrono>
#include <cmath>
#include <ctime>
#include <vector>

namespace microsim::sim::detail {

/// True when the model is finalized, the state is 3 by #N and finite, and every control
/// names a node and has a finite target.
bool validInput(const SpringModel& model, const SpringState& state, const SpringControls& controls);

/// Moves every control node (not fixed) to its target and zeroes its velocity; fixed nodes
/// win over controls. Zeroes the velocity of fixed nodes.
void applyControls(const SpringModel& model, SpringState& state, const SpringControls& controls);

/// Control nodes that pull: not fixed. In the order given, duplicates removed (sorted).
std::vector<int> activeControlNodes(const SpringModel& model, const SpringControls& controls);

/// True when every entry is finite.
bool allFinite(const Points& p);

/// Largest alive-link base stiffness (g/s²).
double maxStiffness(const SpringModel& model);

/// A budget's clock: seconds since the solve started, and whether its time is up.
class Stopwatch {
 public:
  explicit Stopwatch(const SolveBudget& budget)
      : clock_(budget.clock), now_(budget.now), start_(now()),
        deadline_((std::isnan(budget.since) ? start_ : budget.since) + budget.maxSeconds) {}
  double seconds() const { return now() - start_; }
  /// The budget's check: reads the clock once.
  bool expired() const { return now() >= deadline_; }

 private:
  double now() const {
    if (now_) return now_();
    if (clock_ == BudgetClock::ThreadCpu) {
      timespec t{};
      clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
      return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
    }
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
  }

  BudgetClock clock_;
  const ClockFunction& now_;
  double start_;
  double deadline_;
};

/// Residuals above this multiple of the starting one (or of 1, whichever is larger) count
/// as divergence.
inline constexpr double kDivergenceFactor = 1e8;

}  // namespace microsim::sim::detail
