#pragma once
// Exact link lengths by a direct tridiagonal solve: the better-than-paper thread solver.
//
// Follow-the-leader (follow_the_leader.h) keeps every length exactly outward of the leaders
// but averages two passes between leaders, which stretches the links there. This kernel
// projects positions onto the constraint manifold C_i(x) = |x_{i+1} − x_i| − l_i = 0 for all
// intact links, moving each node in proportion to its inverse mass w_i (w = 0: a leader, it
// does not move). It is the "fast projection" of Goldenthal et al. 2007 (Efficient simulation
// of inextensible cloth), which for a chain is exact Gauss–Newton with an O(N) solve:
//
//   u_i = (x_{i+1} − x_i)/|x_{i+1} − x_i|,   ∇_{x_i} C_i = −u_i,  ∇_{x_{i+1}} C_i = u_i
//   (J W Jᵀ + αI) λ = −C,   Δx_i = w_i (λ_{i−1} u_{i−1} − λ_i u_i)
//   (J W Jᵀ)_{ii} = w_i + w_{i+1},   (J W Jᵀ)_{i,i+1} = −w_{i+1} u_i·u_{i+1}
//
// J W Jᵀ couples only neighbouring links, so each iteration is one Thomas sweep (forward
// elimination, back substitution) over the links: O(N) time and memory, no fill-in. A link
// whose two nodes are both leaders gets λ = 0, and a broken link (alive = 0) decouples its
// neighbours, so the pieces solve independently inside the same sweep. The step is damped
// Levenberg–Marquardt style, diag ← (w_i + w_{i+1})(1 + μ): μ starts at 1e-9 (plain
// Gauss–Newton, quadratic convergence near a solution; from a follow-the-leader start
// typically 2–4 sweeps to 1e-12), and a step that does not lower Σ (C_i/l_i)² is undone and
// retried with μ ten times larger. That is what keeps a span pulled straight between leaders
// past its length finite: no solution exists, J W Jᵀ is singular along the span, and the
// damped steps converge to the least-squares spread of the over-length instead of NaN.
//
// Units: millimetres. Positions are 3 by (N + 1); w has N + 1 entries (1/g, any common scale).

#include "microsim/sim/suture/suture_model.h"

#include <cstdint>
#include <span>
#include <vector>

namespace microsim::sim::suture {

struct ChainProjectionResult {
  int iterations = 0;
  double residual = 0.0;  ///< max |C_i| / l_i over intact links at the end
};

/// Reusable buffers (one per solver; nothing else is kept between calls).
struct ChainProjectionScratch {
  std::vector<double> diag, upper, rhs, lambda, c;
  std::vector<Vec3> u;
  Points saved{3, 0};
};

/// Projects x onto exact link lengths with weights w (see the header essay). Stops once the
/// relative residual is ≤ tolerance or after maxIterations sweeps.
ChainProjectionResult projectChainLengths(Points& x, std::span<const double> rest,
                                          std::span<const double> w,
                                          const std::vector<std::uint8_t>& alive,
                                          int maxIterations, double tolerance,
                                          ChainProjectionScratch& scratch);

}  // namespace microsim::sim::suture
