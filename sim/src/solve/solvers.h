#pragma once
// The tissue solvers behind makeSolver. All share the definitions of spring_kernels.h
// (forces, relative residual) and the rules of solver.h: invalid input → InvalidInput
// with the state untouched; divergence → Diverged with the state restored; never NaN.
// An "iteration" is what each solver repeats:
//
// qss       one Gauss–Seidel sweep over the free nodes in NODE-ORDERING wave order
//           (node_ordering.h), in place: x_i += α_i d_i with d_i = f_i + β d_i(previous
//           sweep) (β = SolverParams::momentum, the paper's "CG-style" variant; β = 0 is
//           plain QSS). α is SolverParams::alpha when given (the paper's global, hand-tuned
//           scale), otherwise per node α_i = 1 / Σ_j T'_ij, the sum over i's links of their
//           stiffness dT/dl at the current length: the largest step that cannot overshoot
//           (it bounds the node's 3 by 3 Hessian block from above), i.e. nonlinear
//           Jacobi-scaled Gauss–Seidel. Per-level cutout ε = SolverParams::cutout. The
//           reported residual is the largest |f_i| seen during the last sweep (forces are
//           evaluated just before each node moves; nodes skipped by the cutout are not
//           counted), over forceScale.
// rk4       one cycle of SolverParams::timeStep of Eq. 1, m a + c v = f(x) + m g, by
//           classical RK4 in equal substeps below the stability limit of the stiffest node
//           (h ≤ √(m_i / (2 Σ_j T'_ij)), h c_i / m_i ≤ 1). c_i = model damping + params.damping.
// implicit  one backward-Euler step of SolverParams::timeStep, linearised once
//           (Baraff–Witkin): (M + hC + h²K) Δv = h (f + m g − C v) − h² K v, K the clamped
//           stiffness matrix, solved by block-Jacobi preconditioned CG; then v += Δv,
//           x += h v. The peer every engine ships (SOFA's EulerImplicit + CG).
// newton    one Newton step towards equilibrium f(x) + m g + Σ point springs = 0: K d = f,
//           then a backtracking line search on the total energy (Armijo). On regions under
//           2000 nodes K is the true Hessian (links and the controls' point springs), solved
//           by CG preconditioned with the kept LDLᵀ factors of an earlier Hessian while that
//           takes at most 12 iterations, else factorised anew (sparse LDLᵀ); where the true
//           Hessian is indefinite (compressed links) that iteration takes its PSD projection
//           (per spring, see spring_kernels.h). On regions of 2000 nodes or more K is the
//           true Hessian too, solved by CG to an adaptive relative tolerance (inexact Newton,
//           η = clamp(residual, 1e-4, 1e-2)) preconditioned by smoothed-aggregation
//           multigrid (multigrid.h) built on the projection, its hierarchy kept across
//           iterations and steps until CG slows down; CG stops at a direction of negative
//           curvature with what it has (truncated Newton), or when the first direction
//           has one, solves the projection instead. With SolverParams::activeRegion, the
//           unknowns are only the free nodes the pull reaches (newton_solver.cpp). Honours
//           point springs (point_spring.h).
// reference newton on the whole mesh until the relative residual is ≤ 1e-10 (or the
//           budget's own tolerance when smaller), whatever iteration budget it is given.

#include "microsim/sim/solve/solver.h"

#include <memory>

namespace microsim::sim::detail {

std::unique_ptr<TissueSolver> makeQssSolver(const SolverParams& params);
std::unique_ptr<TissueSolver> makeRk4Solver(const SolverParams& params);
std::unique_ptr<TissueSolver> makeImplicitSolver(const SolverParams& params);
std::unique_ptr<TissueSolver> makeNewtonSolver(const SolverParams& params, bool reference);

}  // namespace microsim::sim::detail
