#pragma once
// Stateless spring kernels: the force, energy and Hessian of one link, and the totals
// every tissue solver shares (forces on all nodes, energy, the relative residual).
// Pure functions in the PositionBasedDynamics style; the math is here, the loops over a
// model are in spring_kernels.cpp.
//
// One link (a, b), rest length r ≥ 0, base stiffness k0, length l = |x_b − x_a|,
// stretch Δ = l − r, unit direction u = (x_b − x_a) / l:
//
//   tension   T(l)  = k0 Δ (1 + c·max(Δ, 0)²)      c = gain / r² (Stiffening), 0 (Constant)
//   energy    E(l)  = k0 (Δ²/2 + c·max(Δ, 0)⁴/4)   so that dE/dl = T
//   force on a      = T u = (T / l)(x_b − x_a)      (on b: the opposite)
//   stiffness T'(l) = k0 (1 + 3c·max(Δ, 0)²)
//
// This is the law of spring_model.h: k(s) = k0 (1 + gain·max(s, 0)²) with strain
// s = Δ / r gives T = k(s) Δ. A zero-rest spring (r = 0) does not stiffen (c = 0, the
// strain is undefined) and is then the linear spring T = k0 l, whose force k0 (x_b − x_a)
// is defined even when the nodes coincide.
//
// The Hessian of E with respect to x_a (3 by 3; the link's 6 by 6 Hessian is
// [H −H; −H H]) is
//
//   H = T' u uᵀ + (T / l)(I − u uᵀ).
//
// The second term is negative for a compressed spring (T < 0), which makes H indefinite;
// the clamped (PSD-projected) Hessian replaces T / l by max(T / l, 0) and T' by
// max(T', 0), the usual projection for Newton on mass–spring systems.
// Below kMinLength the direction u is undefined: the force is then k0 (x_b − x_a) for a
// zero-rest spring and 0 otherwise (coincident nodes of a spring with rest > 0 sit on an
// unstable balance point that their other links break), and H = k0 I stands in.
//
// Units: positions mm, k0 g/s² (force per mm), force g·mm/s² (µN), energy g·mm²/s² (nJ).

#include "microsim/sim/mesh/spring_model.h"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <vector>

namespace microsim::sim {

/// Lengths below this (mm) count as coincident nodes.
inline constexpr double kMinLength = 1e-12;

/// The stiffening coefficient c = gain / r² (1/mm²), 0 for a constant or zero-rest link.
inline double stiffeningCoefficient(const Link& link) {
  if (link.law != StiffnessLaw::Stiffening || link.rest <= kMinLength) return 0.0;
  return link.gain / (link.rest * link.rest);
}

/// Tension T(l) (µN) of a link with base stiffness k, rest length r and stiffening c.
inline double springTension(double k, double rest, double c, double length) {
  const double d = length - rest;
  const double dp = std::max(d, 0.0);
  return k * d * (1.0 + c * dp * dp);
}

/// dT/dl (g/s²).
inline double springTensionDerivative(double k, double rest, double c, double length) {
  const double dp = std::max(length - rest, 0.0);
  return k * (1.0 + 3.0 * c * dp * dp);
}

/// Energy E(l) (nJ).
inline double springEnergy(double k, double rest, double c, double length) {
  const double d = length - rest;
  const double dp2 = std::max(d, 0.0) * std::max(d, 0.0);
  return k * (0.5 * d * d + 0.25 * c * dp2 * dp2);
}

/// T / l, the factor that turns x_b − x_a into the force on a (g/s²). Finite for l → 0
/// only for zero-rest links; callers handle length < kMinLength themselves.
inline double springTensionOverLength(double k, double rest, double c, double length) {
  return springTension(k, rest, c, length) / length;
}

/// Force on node a (µN) of `link` with ends at xa and xb (mm); the force on b is minus it.
inline Vec3 linkForce(const Link& link, const Vec3& xa, const Vec3& xb) {
  const Vec3 d = xb - xa;
  const double l = d.norm();
  if (l < kMinLength) return link.rest <= kMinLength ? Vec3(link.k * d) : Vec3::Zero();
  return springTensionOverLength(link.k, link.rest, stiffeningCoefficient(link), l) * d;
}

/// Energy of `link` (nJ).
inline double linkEnergy(const Link& link, const Vec3& xa, const Vec3& xb) {
  return springEnergy(link.k, link.rest, stiffeningCoefficient(link), (xb - xa).norm());
}

/// ∂²E/∂x_a² of one spring (3 by 3, g/s²); `clamp` projects it to PSD (see above).
inline Eigen::Matrix3d springHessian(double k, double rest, double c, const Vec3& xa,
                                     const Vec3& xb, bool clamp) {
  const Vec3 d = xb - xa;
  const double l = d.norm();
  if (l < kMinLength) return k * Eigen::Matrix3d::Identity();
  const Vec3 u = d / l;
  double t = springTensionDerivative(k, rest, c, l);
  double s = springTensionOverLength(k, rest, c, l);
  if (clamp) {
    t = std::max(t, 0.0);
    s = std::max(s, 0.0);
  }
  return (t - s) * (u * u.transpose()) + s * Eigen::Matrix3d::Identity();
}

inline Eigen::Matrix3d linkHessian(const Link& link, const Vec3& xa, const Vec3& xb,
                                   bool clamp = false) {
  return springHessian(link.k, link.rest, stiffeningCoefficient(link), xa, xb, clamp);
}

/// Which nodes a solve moves: free nodes that are neither fixed nor held by a control.
/// One byte per node, 1 = free.
std::vector<unsigned char> freeMask(const SpringModel& model, const SpringControls& controls);

/// Forces on every node (3 by #N, µN): Σ over alive links of the spring forces plus the
/// weight m_i g. Constrained nodes get their forces too; callers mask them.
void totalForces(const SpringModel& model, const Points& x, Points& forces);
/// Adds the forces of the soft terms (point_spring.h) to `forces` (3 by #N, µN).
void addPointSpringForces(const std::vector<PointSpring>& springs, const Points& x, Points& forces);
/// Total potential energy (nJ): Σ over alive links of E − Σ_i m_i g·x_i over free nodes.
double totalEnergy(const SpringModel& model, const Points& x,
                   const std::vector<unsigned char>& free);

/// The force scale that makes residuals relative (µN):
///   F = max( k_max · d_max,  max_i m_i |g| ),
/// k_max the largest base stiffness of an alive link, d_max the largest distance of a
/// control target from its node's rest position. When both are 0 (nothing pulls), F = k_max
/// times the mean rest length, and 1 if that is 0 too.
double forceScale(const SpringModel& model, const SpringControls& controls);

/// The relative residual every solver reports and stops on:
///   max over free nodes i of |f_i| / forceScale,
/// f_i the total force on node i (links, the controls' soft terms and weight). 0 means exact equilibrium.
/// The controls are assumed applied to x already.
double relativeResidual(const SpringModel& model, const Points& x, const SpringControls& controls);

}  // namespace microsim::sim
