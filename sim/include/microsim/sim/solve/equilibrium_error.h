#pragma once
// How far a tissue state is from the static equilibrium of its controls: the paper's error
// metric (Brown et al. 2002; DESIGN.md, "speed-error"), for any state a solver or a scene
// step left behind, so that benchmarks and tests measure it the same way.
//
//   x*                   the equilibrium the `reference` solver (Newton on the whole mesh to a
//                        relative residual of 1e-10) reaches from a copy of the state, with
//                        the same controls (fixed nodes stay, control nodes sit on their
//                        targets)
//   maxDistance          max_i |x_i − x*_i| over all nodes (mm)
//   controlDisplacement  max_c |target_c − rest_c| over the controls, rest_c the rest position
//                        of control c's node, and over the two-sided point springs (a thread
//                        pulling a pierce) |anchor − rest point| (mm): how far the tools have
//                        moved the tissue; contacts (one-sided) are not controls
//   ratioPercent         100 · maxDistance / controlDisplacement, 0 when controlDisplacement
//                        is 0 (no tool has moved anything, nothing to be wrong about)
//
// The state is not changed. The reference warm-starts from it, so a state close to
// equilibrium costs a few Newton iterations.

#include "microsim/sim/mesh/spring_model.h"

namespace microsim::sim {

struct EquilibriumError {
  double maxDistance = 0.0;          ///< mm, largest node distance to the equilibrium
  double controlDisplacement = 0.0;  ///< mm, largest control target's distance from rest
  double ratioPercent = 0.0;         ///< %, 100 · maxDistance / controlDisplacement
  bool converged = false;            ///< the reference reached its tolerance
};

/// The distance of `state` to the converged equilibrium of `controls` on `model`.
EquilibriumError equilibriumError(const SpringModel& model, const SpringState& state,
                                  const SpringControls& controls);

}  // namespace microsim::sim
