#include "solve/block_system.h"

#include <Eigen/LU>

#include <cmath>

namespace microsim::sim::detail {

void BlockSystem::multiply(const Eigen::VectorXd& p, Eigen::VectorXd& y) const {
  const int n = size();
  y.resize(3 * n);
  // diagonal blocks
  for (int i = 0; i < n; ++i) y.segment<3>(3 * i) = diag[i] * p.segment<3>(3 * i);
  // off-diagonal blocks, both halves
  const double* pp = p.data();
  double* yy = y.data();
  for (const Off& o : off) {
    const double* pa = pp + 3 * o.a;
    const double* pb = pp + 3 * o.b;
    double* ya = yy + 3 * o.a;
    double* yb = yy + 3 * o.b;
    const SymBlock& m = o.m;
    ya[0] += m.xx * pb[0] + m.xy * pb[1] + m.xz * pb[2];
    ya[1] += m.xy * pb[0] + m.yy * pb[1] + m.yz * pb[2];
    ya[2] += m.xz * pb[0] + m.yz * pb[1] + m.zz * pb[2];
    yb[0] += m.xx * pa[0] + m.xy * pa[1] + m.xz * pa[2];
    yb[1] += m.xy * pa[0] + m.yy * pa[1] + m.yz * pa[2];
    yb[2] += m.xz * pa[0] + m.yz * pa[1] + m.zz * pa[2];
  }
}

Eigen::Matrix3d invertBlock(const Eigen::Matrix3d& m) {
  const double scale = std::max(m.trace(), 1e-300);
  const double det = m.determinant();
  if (std::isfinite(det) && det > 1e-12 * scale * scale * scale) return m.inverse();
  return (m + 1e-6 * scale * Eigen::Matrix3d::Identity()).inverse();
}

PcgResult solvePcg(const BlockSystem& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                   double tolerance, int maxIterations) {
  const int n = a.size();
  PcgResult result;
  x = Eigen::VectorXd::Zero(3 * n);
  const double bNorm = b.norm();
  if (!(bNorm > 0.0)) return result;

  std::vector<Eigen::Matrix3d> inv(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) inv[i] = invertBlock(a.diag[i]);
  auto precondition = [&](const Eigen::VectorXd& r, Eigen::VectorXd& z) {
    z.resize(3 * n);
    for (int i = 0; i < n; ++i) z.segment<3>(3 * i) = inv[i] * r.segment<3>(3 * i);
  };

  Eigen::VectorXd r = b;
  Eigen::VectorXd z, p, q;
  precondition(r, z);
  p = z;
  double rz = r.dot(z);
  double rNorm = bNorm;
  while (result.iterations < maxIterations && rNorm > tolerance * bNorm) {
    a.multiply(p, q);
    const double pq = p.dot(q);
    if (!(pq > 0.0) || !std::isfinite(pq)) {
      result.ok = result.iterations > 0;
      break;
    }
    const double step = rz / pq;
    x += step * p;
    r -= step * q;
    ++result.iterations;
    rNorm = r.norm();
    precondition(r, z);
    const double rzNew = r.dot(z);
    p = z + (rzNew / rz) * p;
    rz = rzNew;
  }
  result.relativeResidual = rNorm / bNorm;
  return result;
}

}  // namespace microsim::sim::detail
