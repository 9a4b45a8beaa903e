#include "microsim/sim/suture/chain_projection.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace microsim::sim::suture {

namespace {

constexpr double kMinDamping = 1e-9;
constexpr double kMaxDamping = 1e6;
constexpr double kStagnation = 0.99;  // an accepted step keeping this much of Σ C² has stalled
constexpr int kStalledSteps = 3;      // stalled accepted steps in a row that end the loop
constexpr double kCarryShare = 0.25;  // largest chord change carried, as a share of the slack

struct Residual {
  double worst = 0.0;    // max |C_i| / l_i
  double squares = 0.0;  // Σ (C_i / l_i)²
};

// constraint values and directions over the solvable links
Residual evaluate(const Points& x, std::span<const double> rest, std::span<const double> w,
                  const std::vector<std::uint8_t>& alive, ChainProjectionScratch& s) {
  const std::size_t links = rest.size();
  const double* p = x.data();
  Residual r;
  for (std::size_t i = 0; i < links; ++i, p += 3) {
    const double ex = p[3] - p[0];
    const double ey = p[4] - p[1];
    const double ez = p[5] - p[2];
    const double len = std::sqrt(ex * ex + ey * ey + ez * ez);
    if (len > 0.0) {
      const double inv = 1.0 / len;
      s.u[i] = Vec3(ex * inv, ey * inv, ez * inv);
    } else {
      s.u[i] = Vec3::UnitX();
    }
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
  // Δx_i = w_i (λ_{i−1} u_{i−1} − λ_i u_i): each link pushes its two ends apart
  for (std::size_t i = 0; i < links; ++i) {
    if (!alive[i]) continue;
    const Vec3 f = s.lambda[i] * s.u[i];
    x.col(static_cast<Eigen::Index>(i)) -= w[i] * f;
    x.col(static_cast<Eigen::Index>(i + 1)) += w[i + 1] * f;
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
  int stalled = 0;
  while (result.iterations < maxIterations && now.worst > tolerance) {
    s.saved = x;
    gaussNewtonStep(x, rest, w, alive, mu, s);
    ++result.iterations;
    const Residual next = evaluate(x, rest, w, alive, s);
    if (next.squares < now.squares) {
      // an over-long span has no solution: stop once the spread has stalled
      stalled = next.squares > kStagnation * now.squares ? stalled + 1 : 0;
      now = next;
      mu = std::max(kMinDamping, mu * 0.1);
      if (stalled >= kStalledSteps) break;
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

void carrySpans(const SutureModel& model, Points& x, const std::vector<std::uint8_t>& alive,
                std::span<const Leader> leaders) {
  for (std::size_t k = 0; k + 1 < leaders.size(); ++k) {
    const int a = leaders[k].node;
    const int b = leaders[k + 1].node;
    if (b - a < 2) continue;
    // only within one piece
    bool intact = true;
    for (int l = a; l < b && intact; ++l) intact = alive[static_cast<std::size_t>(l)] != 0;
    if (!intact) continue;

    const Vec3 pa = x.col(a);
    const Vec3 pb = x.col(b);
    const Vec3& qa = leaders[k].position;
    const Vec3& qb = leaders[k + 1].position;
    const Vec3 e = pb - pa;
    const Vec3 e2 = qb - qa;
    const double c = e.norm();
    const double c2 = e2.norm();
    if (!(c > 0.0) || !(c2 > 0.0)) {
      // no chord to carry along: translate by the mean end motion
      const Vec3 shift = 0.5 * ((qa - pa) + (qb - pb));
      for (int i = a + 1; i < b; ++i) x.col(i) += shift;
      continue;
    }
    const double arc = model.arc(a, b);
    const double slack = arc - c;
    const double slack2 = std::max(0.0, arc - c2);
    const bool small = std::abs(c2 - c) <= kCarryShare * std::max(slack, 0.0);
    const bool taut = std::min(c, c2) >= arc;
    if (!small && !taut) {
      // a chord change large against the slack (a jump, or a straight span pushed shorter):
      // the paper's two averaged passes
      const Leader ends[2] = {leaders[k], leaders[k + 1]};
      followTheLeader(x, model.restLengths(), a, b, ends);
      continue;
    }
    const Vec3 dir = e / c;
    const Vec3 dir2 = e2 / c2;
    const Eigen::Matrix3d turn = Eigen::Quaterniond::FromTwoVectors(dir, dir2).toRotationMatrix();
    const double scale = slack > 0.0 ? std::sqrt(slack2 / slack) : 1.0;
    const double stretch = c2 / c;
    for (int i = a + 1; i < b; ++i) {
      const Vec3 r = x.col(i) - pa;
      const double along = r.dot(dir);
      x.col(i) = qa + (along * stretch) * dir2 + scale * (turn * (r - along * dir));
    }
  }
}

}  // namespace microsim::sim::suture
