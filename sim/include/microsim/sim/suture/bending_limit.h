#pragma once
// A bending limit for the free thread: no turn sharper than a maximum angle between two
// consecutive links.
//
// Follow-the-leader and the length projection keep link lengths but not the angles between
// links, so a free tail dragged at hand speed folds into hairpins (turns near π between
// consecutive links), which real monofilament cannot do and which crowd the self-contact
// broad phase with close link pairs. For node i with links of rest lengths a = l_{i−1} and
// b = l_i, the turn θ between their directions satisfies
//     |x_{i+1} − x_{i−1}|² = a² + b² + 2ab·cos θ      (at rest lengths),
// so θ ≤ θmax exactly when |x_{i+1} − x_{i−1}| ≥ d_min, d_min² = a² + b² + 2ab·cos θmax.
// A pair closer than d_min is pushed apart symmetrically along its difference to d_min (a
// one-sided distance constraint, position based); node i stays, and the solver's length
// restore that follows moves it back onto the lengths. One Gauss–Seidel sweep per call: the
// limit is approached over the substeps' rounds, it is a shape hint, not a hard constraint.
// Only turns sharper than θmax are touched (the default 2π/3 leaves a knot's or a jaw wrap's
// bends alone), and only where node i and both neighbours are free (not held, not in any
// contact) and both links are intact.
//
// Units: millimetres, radians. Positions are 3 by (N + 1).

#include "microsim/sim/suture/suture_model.h"

#include <cstdint>
#include <span>
#include <vector>

namespace microsim::sim::suture {

/// Default largest turn between consecutive free links (rad): 120°.
inline constexpr double kDefaultMaxTurn = 2.0943951023931957;

/// Pushes apart the outer nodes of every free turn sharper than maxTurn (rad, in (0, π); other
/// values do nothing); free[k] != 0 marks nodes the limit may move, alive[l] != 0 intact links.
/// Returns the number of turns corrected.
int limitBending(Points& x, std::span<const double> rest, const std::vector<std::uint8_t>& alive,
                 std::span<const std::uint8_t> free, double maxTurn);

/// The largest turn (rad) between consecutive intact links over nodes [first, last].
double maxTurnAngle(const Points& x, const std::vector<std::uint8_t>& alive, int first, int last);

}  // namespace microsim::sim::suture
