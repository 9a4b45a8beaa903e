#include "solve/block_system.h"

#include <Eigen/LU>

#include <algorithm>
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

Eigen::SparseMatrix<double, Eigen::RowMajor> BlockSystem::toSparse() const {
  const int n = size();
  // per node: its neighbour nodes (itself included) and their blocks, sorted by node
  std::vector<int> start(static_cast<std::size_t>(n) + 1, 1);
  start[n] = 0;
  for (const Off& o : off) {
    ++start[o.a];
    ++start[o.b];
  }
  int total = 0;
  for (int i = 0; i <= n; ++i) {
    const int count = i < n ? start[i] : 0;
    start[i] = total;
    total += count;
  }
  struct Entry {
    int node;
    int block;  ///< index into off, or −1 for the diagonal
  };
  std::vector<Entry> entries(static_cast<std::size_t>(total));
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (int i = 0; i < n; ++i) entries[fill[i]++] = {i, -1};
  for (int k = 0; k < static_cast<int>(off.size()); ++k) {
    entries[fill[off[k].a]++] = {off[k].b, k};
    entries[fill[off[k].b]++] = {off[k].a, k};
  }
  for (int i = 0; i < n; ++i)
    std::sort(entries.begin() + start[i], entries.begin() + start[i + 1],
              [](const Entry& l, const Entry& r) { return l.node < r.node; });

  // three scalar rows per node, three columns per neighbour
  Eigen::SparseMatrix<double, Eigen::RowMajor> s(3 * n, 3 * n);
  s.resizeNonZeros(9 * total);
  int* outer = s.outerIndexPtr();
  int* inner = s.innerIndexPtr();
  double* value = s.valuePtr();
  int nz = 0;
  for (int i = 0; i < n; ++i)
    for (int row = 0; row < 3; ++row) {
      outer[3 * i + row] = nz;
      for (int e = start[i]; e < start[i + 1]; ++e) {
        const Entry& entry = entries[e];
        const Eigen::Matrix3d block = entry.block < 0 ? diag[i] : off[entry.block].m.full();
        for (int col = 0; col < 3; ++col) {
          inner[nz] = 3 * entry.node + col;
          value[nz] = block(row, col);
          ++nz;
        }
      }
    }
  outer[3 * n] = nz;
  return s;
}

BlockJacobi::BlockJacobi(const BlockSystem& a) : inverse_(static_cast<std::size_t>(a.size())) {
  for (int i = 0; i < a.size(); ++i) inverse_[i] = invertBlock(a.diag[i]);
}

void BlockJacobi::apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  const int n = static_cast<int>(inverse_.size());
  z.resize(3 * n);
  for (int i = 0; i < n; ++i) z.segment<3>(3 * i) = inverse_[i] * r.segment<3>(3 * i);
}

PcgResult solvePcg(const BlockSystem& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                   double tolerance, int maxIterations) {
  return solvePcg(a, BlockJacobi(a), b, x, tolerance, maxIterations);
}

PcgResult solvePcg(const BlockSystem& a, const Preconditioner& m, const Eigen::VectorXd& b,
                   Eigen::VectorXd& x, double tolerance, int maxIterations) {
  const int n = a.size();
  PcgResult result;
  x = Eigen::VectorXd::Zero(3 * n);
  const double bNorm = b.norm();
  if (!(bNorm > 0.0)) return result;

  Eigen::VectorXd r = b;
  Eigen::VectorXd z, p, q;
  m.apply(r, z);
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
    // done: no preconditioner for a direction that will not be taken (a solve with the
    // factors, or a multigrid cycle, every call)
    if (result.iterations >= maxIterations || !(rNorm > tolerance * bNorm)) break;
    m.apply(r, z);
    const double rzNew = r.dot(z);
    if (!(rzNew > 0.0) || !std::isfinite(rzNew)) break;
    p = z + (rzNew / rz) * p;
    rz = rzNew;
  }
  result.relativeResidual = rNorm / bNorm;
  return result;
}

}  // namespace microsim::sim::detail
