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
// A span pulled nearly straight between two leaders is where Gauss–Newton is weak: the
// lengths depend on the nodes' sideways positions only to second order, J W Jᵀ is nearly
// singular along the span, and a leader move of a link length can take a hundred damped
// sweeps. The predictor carrySpans removes that: before the projection, each span between two
// consecutive leaders a < b is carried with its ends, from where its end nodes are (p_a, p_b)
// to the leaders' positions (q_a, q_b). With chord c = |p_b − p_a|, c' = |q_b − q_a|,
// directions d, d', R the shortest rotation taking d to d' and S the span's rest arc, node k
// at r = x_k − p_a = α d + r⊥ goes to
//     x_k ← q_a + α (c'/c) d' + s R r⊥,      s = √((S − c')/(S − c))
// — the chord stretched to its new length, the sag scaled so that a shallow span keeps its arc
// (S − c ≈ ∫ y'²/2 for sideways offsets y), which is exact to first order in c' − c. So it is
// used when |c' − c| ≤ (S − c)/4, or when the span is taut before and after (c, c' ≥ S);
// otherwise (a jump, or a straight span pushed shorter, which has no sag to scale) the span
// takes the paper's two averaged passes (follow_the_leader.h), which bend it. A taut span moved
// by hand-speed steps then projects in 2–4 sweeps at 200 links, under ten at 2000. An
// over-long span (c' > S) comes out straight, its excess spread evenly; the projection then
// stops once three steps in a row each lower Σ C² by less than 1 %.
//
// Units: millimetres. Positions are 3 by (N + 1); w has N + 1 entries (1/g, any common scale).

#include "microsim/sim/suture/follow_the_leader.h"
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
/// relative residual is ≤ tolerance, after maxIterations sweeps, or when three accepted sweeps
/// in a row each lower Σ (C_i/l_i)² by less than 1 % (an over-long span).
ChainProjectionResult projectChainLengths(Points& x, std::span<const double> rest,
                                          std::span<const double> w,
                                          const std::vector<std::uint8_t>& alive,
                                          int maxIterations, double tolerance,
                                          ChainProjectionScratch& scratch);

/// The span predictor of the header essay: carries every span between two consecutive leaders
/// (sorted by node, unique; intact links between them) from its end nodes' current positions
/// to the leaders' positions. Nodes outside the spans and the leader nodes do not move.
void carrySpans(const SutureModel& model, Points& x, const std::vector<std::uint8_t>& alive,
                std::span<const Leader> leaders);

}  // namespace microsim::sim::suture
