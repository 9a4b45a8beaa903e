#include "microsim/sim/suture/chain_projection.h"

#include <algorithm>
#include <cmath>

namespace microsim::sim::suture {

namespace {

constexpr double kMinDamping = 1e-9;
constexpr double kMaxDamping = 1e6;

struct Residual {
  double worst = 0.0;    // max |C_i| / l_i
  double squares = 0.0;  // Σ (C_i / l_i)²
};

// constraint values and directions over the solvable links
Residual evaluate(const Points& x, std::span<const double> rest, std::span<const double> w,
                  const std::vector<std::uint8_t>& alive, ChainProjectionScratch& s) {
  const std::size_t links = rest.size();
  Residual r;
  for (std::size_t i = 0; i < links; ++i) {
    const Vec3 e = x.col(static_cast<Eigen::Index>(i + 1)) - x.col(static_cast<Eigen::Index>(i));
    const double len = e.norm();
    s.u[i] = len > 0.0 ? Vec3(e / len) : Vec3::UnitX();
    const bool solvable = alive[i] && w[i] + w[i + 1] > 0.0;
    s.c[i] = solvable ? len - rest[i] : 0.0;
    const double rel = s.c[i] / rest[i];
    r.worst = std::max(r.worst, std::abs(rel));
    r.squares += rel * rel;
  }
  return r;
}

// one damped Gauss–Newton step: (J W Jᵀ + μ diag) λ = −C by Thomas, then x += W Jᵀ λ
void gaussNewtonStep(Points& x, std::span<const double> rest, std::span<const double> w,
                     const std::vector<std::uint8_t>& alive, double mu,
                     ChainProjectionScratch& s) {
  const std::size_t links = rest.size();
  // assemble; unsolvable links get an identity row
  for (std::size_t i = 0; i < links; ++i) {
    const double wsum = w[i] + w[i + 1];
    const bool solvable = alive[i] && wsum > 0.0;
    s.diag[i] = solvable ? wsum * (1.0 + mu) : 1.0;
    s.rhs[i] = -s.c[i];
    s.upper[i] = 0.0;
    if (i + 1 < links && solvable && alive[i + 1] && w[i + 1] + w[i + 2] > 0.0)
      s.upper[i] = -w[i + 1] * s.u[i].dot(s.u[i + 1]);
  }
  // forward elimination (symmetric: the lower band equals the upper)
  for (std::size_t i = 1; i < links; ++i) {
    const double m = s.upper[i - 1] / s.diag[i - 1];
    s.diag[i] -= m * s.upper[i - 1];
    s.rhs[i] -= m * s.rhs[i - 1];
  }
  // back substitution
  for (std::size_t k = links; k-- > 0;) {
    const double next = k + 1 < links ? s.upper[k] * s.lambda[k + 1] : 0.0;
    s.lambda[k] = (s.rhs[k] - next) / s.diag[k];
  }
  // Δx_i = w_i (λ_{i−1} u_{i−1} − λ_i u_i)
  for (std::size_t i = 0; i <= links; ++i) {
    if (w[i] == 0.0) continue;
    Vec3 dx = Vec3::Zero();
    if (i > 0 && alive[i - 1]) dx += s.lambda[i - 1] * s.u[i - 1];
    if (i < links && alive[i]) dx -= s.lambda[i] * s.u[i];
    x.col(static_cast<Eigen::Index>(i)) += w[i] * dx;
  }
}

}  // namespace

ChainProjectionResult projectChainLengths(Points& x, std::span<const double> rest,
                                          std::span<const double> w,
                                          const std::vector<std::uint8_t>& alive,
                                          int maxIterations, double tolerance,
                                          ChainProjectionScratch& s) {
  const std::size_t links = rest.size();
  s.diag.resize(links);
  s.upper.resize(links);
  s.rhs.resize(links);
  s.lambda.resize(links);
  s.c.resize(links);
  s.u.resize(links);

  // Levenberg–Marquardt on Σ C²: a step that does not lower it is undone and damped harder
  ChainProjectionResult result;
  Residual now = evaluate(x, rest, w, alive, s);
  double mu = kMinDamping;
  while (result.iterations < maxIterations && now.worst > tolerance) {
    s.saved = x;
    gaussNewtonStep(x, rest, w, alive, mu, s);
    ++result.iterations;
    const Residual next = evaluate(x, rest, w, alive, s);
    if (next.squares < now.squares) {
      now = next;
      mu = std::max(kMinDamping, mu * 0.1);
      continue;
    }
    x = s.saved;
    now = evaluate(x, rest, w, alive, s);
    mu *= 10.0;
    if (mu > kMaxDamping) break;
  }
  result.residual = now.worst;
  return result;
}

}  // namespace microsim::sim::suture
