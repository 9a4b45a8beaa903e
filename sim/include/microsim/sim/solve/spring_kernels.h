#pragma once
// Stateless spring kernels: the force, energy and Hessian of one link, and the totals
// every tissue solver shares (forces on all nodes, energy, the relative residual).
// Pure functions in the PositionBasedDynamics style; the math is here, the loops over a
// model are in spring_kernels.cpp.
//
// One link (a, b), rest length r ≥ 0, base stiffness k0, length l = |x_b − x_a|,
// stretch Δ = l − r, strain s = Δ / r, unit direction u = (x_b − x_a) / l. The laws of
// spring_model.h, written in Δ so that the kernels never divide by r:
//
//   Constant     T(l) = k0 Δ                           E(l) = k0 Δ²/2
//   Stiffening   T(l) = k0 Δ (1 + c·Δ₊²)                E(l) = k0 (Δ²/2 + c·Δ₊⁴/4)
//                c = gain / r² (1/mm²), Δ₊ = max(Δ, 0); this is k(s) = k0 (1 + gain·s₊²)
//   Exponential  for Δ > 0, with β = b / r (1/mm), b = gain (Fung's exponent), x = βΔ = b s:
//                T(l) = k0 (e^x − 1)/β  = k0 r (e^{b s} − 1)/b
//                T'(l) = k0 e^x
//                E(l) = k0 (e^x − 1 − x)/β²  = k0 r² (e^{b s} − 1 − b s)/b²
//                for Δ ≤ 0 the constant law: T, T' and E meet it with value and slope at
//                Δ = 0 (T is C¹, E is C²), so compression stays linear
//   force on a      = T u = (T / l)(x_b − x_a)      (on b: the opposite)
//
// Fung, "Biomechanics: mechanical properties of living tissues" (2nd ed., 1993), ch. 8:
// the exponential stress–strain law of soft tissue, here in one dimension per link.
//
// Overflow guard (Exponential): past the knee Δ* = min(kExpStrainCap·r, kExpMaxExponent/β)
// — strain 5 (the link at 6× its rest length) or an exponent of 50, whichever comes first —
// the law continues linearly with the knee's slope: T = T* + T'*·(Δ − Δ*), T' = T'*,
// E = E* + T*·(Δ − Δ*) + T'*·(Δ − Δ*)²/2. Tissue tears long before (scene limits, strain
// ≈ 0.6), so the knee only keeps a wild solver iterate finite; T, T' and E stay continuous.
//
// A zero-rest spring (r = 0) does not stiffen (the strain is undefined) and is then the
// linear spring T = k0 l, whose force k0 (x_b − x_a) is defined even when the nodes
// coincide; an exponential link with b ≤ 0 is the constant law (its b → 0 limit).
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
#include "microsim/sim/solve/exponential.h"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <vector>

namespace microsim::sim {

/// Lengths below this (mm) count as coincident nodes.
inline constexpr double kMinLength = 1e-12;

/// Exponential law: the strain (l − r)/r past which the law continues linearly.
inline constexpr double kExpStrainCap = 5.0;
/// Exponential law: the largest exponent b·s evaluated, whatever b (e^50 ≈ 5·10²¹).
inline constexpr double kExpMaxExponent = 50.0;

/// How a link stiffens, in the per-stretch terms the kernels use; both zero for a linear
/// link, at most one nonzero. Two doubles, so solvers can cache it per neighbour.
struct Stiffening {
  double c = 0.0;     ///< Stiffening law: gain / r² (1/mm²)
  double beta = 0.0;  ///< Exponential law: b / r (1/mm)

  /// True when T' = k0 at every length (the constant law).
  bool linear() const { return c == 0.0 && beta == 0.0; }
};

/// The stiffening terms of `link`: zero for a constant, zero-rest or b ≤ 0 link.
inline Stiffening stiffeningCoefficient(const Link& link) {
  if (link.rest <= kMinLength) return {};
  if (link.law == StiffnessLaw::Stiffening) return {link.gain / (link.rest * link.rest), 0.0};
  if (link.law == StiffnessLaw::Exponential && link.gain > 0.0)
    return {0.0, link.gain / link.rest};
  return {};
}

namespace detail {

/// The knee Δ* (mm) of an exponential link with rest r and rate β (see the header).
inline double springExpKnee(double rest, double beta) {
  return std::min(kExpStrainCap * rest, kExpMaxExponent / beta);
}

/// Exponential law for x = βΔ ≥ 0: e^x − 1 and e^x − 1 − x, the latter by its series for
/// small x, where the difference would cancel.
inline constexpr double kSeriesBelow = 1e-2;
inline double springExpm1(double x) {
  return exponentialMinusOne(x);
}
inline double springExpm1MinusX(double x) {
  if (x < kSeriesBelow)
    return x * x * (0.5 + x * (1.0 / 6.0 + x * (1.0 / 24.0 + x * (1.0 / 120.0 + x / 720.0))));
  return exponentialMinusOne(x) - x;
}

}  // namespace detail

/// T and E of one spring at one length, from one e^x − 1 (and an e^x past the knee): what a
/// Newton iteration needs of a link at every position it tries. T' (springTensionDerivative,
/// one e^x) only the positions it goes on from need.
struct SpringTerms {
  double tension = 0.0;  ///< T (µN)
  double energy = 0.0;   ///< E (nJ)
};

/// T and E of a link with base stiffness k, rest length r and stiffening c (see the header).
inline SpringTerms springTerms(double k, double rest, const Stiffening& c, double length) {
  const double d = length - rest;
  if (c.beta > 0.0 && d > 0.0) {
    const double knee = detail::springExpKnee(rest, c.beta);
    const double x = c.beta * std::min(d, knee);
    const double em1 = detail::springExpm1(x);
    const double t = k * em1 / c.beta;
    const double e =
        k * (x < detail::kSeriesBelow ? detail::springExpm1MinusX(x) : em1 - x) / (c.beta * c.beta);
    if (d <= knee) return {t, e};
    const double over = d - knee;
    const double slope = k * detail::exponential(x);  // x is at the knee
    return {t + slope * over, e + t * over + 0.5 * slope * over * over};
  }
  const double dp = std::max(d, 0.0);
  return {k * d * (1.0 + c.c * dp * dp), k * (0.5 * d * d + 0.25 * c.c * (dp * dp) * (dp * dp))};
}

/// Tension T(l) (µN).
inline double springTension(double k, double rest, const Stiffening& c, double length) {
  return springTerms(k, rest, c, length).tension;
}

/// dT/dl (g/s²).
inline double springTensionDerivative(double k, double rest, const Stiffening& c, double length) {
  const double d = length - rest;
  if (c.beta > 0.0 && d > 0.0)
    return k * detail::exponential(c.beta * std::min(d, detail::springExpKnee(rest, c.beta)));
  const double dp = std::max(d, 0.0);
  return k * (1.0 + 3.0 * c.c * dp * dp);
}

/// Energy E(l) (nJ).
inline double springEnergy(double k, double rest, const Stiffening& c, double length) {
  return springTerms(k, rest, c, length).energy;
}

/// T / l, the factor that turns x_b − x_a into the force on a (g/s²). Finite for l → 0
/// only for zero-rest links; callers handle length < kMinLength themselves.
inline double springTensionOverLength(double k, double rest, const Stiffening& c, double length) {
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
/// The same from T' and T / l known at the length l = |d| ≥ kMinLength, d = x_b − x_a.
inline Eigen::Matrix3d springHessianOf(double derivative, double tensionOverLength, const Vec3& d,
                                       double l, bool clamp) {
  const Vec3 u = d / l;
  double t = derivative;
  double s = tensionOverLength;
  if (clamp) {
    t = std::max(t, 0.0);
    s = std::max(s, 0.0);
  }
  return (t - s) * (u * u.transpose()) + s * Eigen::Matrix3d::Identity();
}

inline Eigen::Matrix3d springHessian(double k, double rest, const Stiffening& c, const Vec3& xa,
                                     const Vec3& xb, bool clamp) {
  const Vec3 d = xb - xa;
  const double l = d.norm();
  if (l < kMinLength) return k * Eigen::Matrix3d::Identity();
  return springHessianOf(springTensionDerivative(k, rest, c, l),
                         springTensionOverLength(k, rest, c, l), d, l, clamp);
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
