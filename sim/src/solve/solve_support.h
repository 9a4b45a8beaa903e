#pragma once
// What every solver does around its iterations: reject bad input without touching the
// state, impose the controls, watch the clock, and decide divergence.

#include "microsim/sim/solve/solver.h"

#include <chrono>
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

class Stopwatch {
 public:
  Stopwatch() : start_(std::chrono::steady_clock::now()) {}
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_;
};

/// Residuals above this multiple of the starting one (or of 1, whichever is larger) count
/// as divergence.
inline constexpr double kDivergenceFactor = 1e8;

}  // namespace microsim::sim::detail
