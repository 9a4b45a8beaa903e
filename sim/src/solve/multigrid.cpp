#include "solve/multigrid.h"

#include <Eigen/QR>

#include <algorithm>
#include <cmath>

namespace microsim::sim::detail {
namespace {

using RowMatrix = AggregationMultigrid::RowMatrix;

/// Levels with at most this many unknowns are factored.
constexpr int kCoarseUnknowns = 400;
/// A coarsest level above this many unknowns is smoothed instead of factored.
constexpr int kFactorLimit = 4000;
constexpr int kMaxLevels = 12;
/// Strength threshold θ on level 0; halved on every coarser level.
constexpr double kStrength = 0.08;
/// Rigid motions: 3 translations, 3 rotations.
constexpr int kModes = 6;

/// Node of every unknown, from the first unknown of every node (`start`, #nodes + 1).
std::vector<int> nodeOfUnknown(const std::vector<int>& start) {
  std::vector<int> node(static_cast<std::size_t>(start.back()));
  for (int i = 0; i + 1 < static_cast<int>(start.size()); ++i)
    for (int d = start[i]; d < start[i + 1]; ++d) node[d] = i;
  return node;
}

/// Aggregate of every node (ids 0..count−1): standard three-phase aggregation over the
/// strong couplings ‖A_ij‖_F ≥ θ √(‖A_ii‖_F ‖A_jj‖_F).
std::vector<int> aggregate(const RowMatrix& a, const std::vector<int>& start, double theta,
                           int& count) {
  const int n = static_cast<int>(start.size()) - 1;
  const std::vector<int> nodeOf = nodeOfUnknown(start);

  // squared Frobenius norms of the node blocks, diagonal first
  std::vector<double> self(static_cast<std::size_t>(n), 0.0);
  for (int i = 0; i < n; ++i)
    for (int row = start[i]; row < start[i + 1]; ++row)
      for (RowMatrix::InnerIterator it(a, row); it; ++it)
        if (nodeOf[it.index()] == i) self[i] += it.value() * it.value();
  std::vector<int> strongStart(1, 0), strong;
  std::vector<double> w(static_cast<std::size_t>(n), 0.0);
  std::vector<int> touched;
  for (int i = 0; i < n; ++i) {
    touched.clear();
    for (int row = start[i]; row < start[i + 1]; ++row)
      for (RowMatrix::InnerIterator it(a, row); it; ++it) {
        const int j = nodeOf[it.index()];
        if (j == i) continue;
        if (w[j] == 0.0) touched.push_back(j);
        w[j] += it.value() * it.value();
      }
    std::sort(touched.begin(), touched.end());
    const double si = std::sqrt(self[i]);
    for (int j : touched) {
      if (w[j] >= theta * theta * si * std::sqrt(self[j])) strong.push_back(j);
      w[j] = 0.0;
    }
    strongStart.push_back(static_cast<int>(strong.size()));
  }

  // phase 1: a node whose strong neighbours are all free roots an aggregate of them
  std::vector<int> of(static_cast<std::size_t>(n), -1);
  count = 0;
  for (int i = 0; i < n; ++i) {
    if (of[i] >= 0) continue;
    bool freeAround = true;
    for (int e = strongStart[i]; e < strongStart[i + 1] && freeAround; ++e)
      freeAround = of[strong[e]] < 0;
    if (!freeAround || strongStart[i] == strongStart[i + 1]) continue;
    of[i] = count;
    for (int e = strongStart[i]; e < strongStart[i + 1]; ++e) of[strong[e]] = count;
    ++count;
  }
  // phase 2: the rest join a neighbouring aggregate of phase 1
  const std::vector<int> first = of;
  for (int i = 0; i < n; ++i) {
    if (of[i] >= 0) continue;
    for (int e = strongStart[i]; e < strongStart[i + 1]; ++e)
      if (first[strong[e]] >= 0) {
        of[i] = first[strong[e]];
        break;
      }
  }
  // phase 3: what is left groups with its free strong neighbours (or alone)
  for (int i = 0; i < n; ++i) {
    if (of[i] >= 0) continue;
    of[i] = count;
    for (int e = strongStart[i]; e < strongStart[i + 1]; ++e)
      if (of[strong[e]] < 0) of[strong[e]] = count;
    ++count;
  }
  return of;
}

/// ρ(D⁻¹ A) by power iteration from a fixed start.
double spectralRadius(const RowMatrix& a, const Eigen::VectorXd& inverseDiagonal) {
  const Eigen::Index n = a.rows();
  Eigen::VectorXd v(n), y;
  for (Eigen::Index i = 0; i < n; ++i) v[i] = 1.0 + static_cast<double>(i % 7) / 7.0;
  v.normalize();
  double rho = 1.0;
  for (int k = 0; k < 15; ++k) {
    y = inverseDiagonal.asDiagonal() * (a * v);
    rho = y.norm();
    if (!(rho > 0.0) || !std::isfinite(rho)) return 1.0;
    v = y / rho;
  }
  return rho;
}

void gaussSeidel(const RowMatrix& a, const Eigen::VectorXd& inverseDiagonal,
                 const Eigen::VectorXd& b, Eigen::VectorXd& x, bool forward) {
  const int n = static_cast<int>(a.rows());
  const int* outer = a.outerIndexPtr();
  const int* inner = a.innerIndexPtr();
  const double* value = a.valuePtr();
  double* xx = x.data();
  for (int k = 0; k < n; ++k) {
    const int i = forward ? k : n - 1 - k;
    double s = b[i];
    for (int e = outer[i]; e < outer[i + 1]; ++e) s -= value[e] * xx[inner[e]];
    xx[i] += s * inverseDiagonal[i];
  }
}

Eigen::VectorXd inverseDiagonalOf(const RowMatrix& a) {
  Eigen::VectorXd d = a.diagonal();
  for (Eigen::Index i = 0; i < d.size(); ++i) d[i] = d[i] > 0.0 ? 1.0 / d[i] : 0.0;
  return d;
}

}  // namespace

bool AggregationMultigrid::build(const BlockSystem& system, const Eigen::Matrix3Xd& positions) {
  levels_.clear();
  factored_ = false;
  const int n = system.size();
  jacobi_.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) jacobi_[i] = invertBlock(system.diag[i]);

  // level 0, its block rows, and its rigid motions about the centroid
  levels_.push_back({system.toSparse(), {}, {}, {}});
  levels_[0].inverseDiagonal = inverseDiagonalOf(levels_[0].a);
  {
    const RowMatrix& a = levels_[0].a;
    const int* outer = a.outerIndexPtr();
    const int* inner = a.innerIndexPtr();
    const double* value = a.valuePtr();
    fine_.start.assign(1, 0);
    fine_.column.clear();
    fine_.value.clear();
    fine_.inverseDiagonal.resize(9 * static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
      const int blocks = (outer[3 * i + 1] - outer[3 * i]) / 3;
      for (int k = 0; k < blocks; ++k) {
        fine_.column.push_back(inner[outer[3 * i] + 3 * k] / 3);
        for (int row = 0; row < 3; ++row)
          for (int col = 0; col < 3; ++col) fine_.value.push_back(value[outer[3 * i + row] + 3 * k + col]);
      }
      fine_.start.push_back(fine_.start.back() + blocks);
      Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(fine_.inverseDiagonal.data() + 9 * i) =
          jacobi_[i];
    }
  }
  std::vector<int> start(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i) start[i] = 3 * i;
  const Eigen::Vector3d centroid = n > 0 ? Eigen::Vector3d(positions.rowwise().mean()) : Eigen::Vector3d::Zero();
  Eigen::MatrixXd modes = Eigen::MatrixXd::Zero(3 * n, kModes);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d p = positions.col(i) - centroid;
    modes.block<3, 3>(3 * i, 0).setIdentity();
    modes.block<3, 3>(3 * i, 3) << 0, p.z(), -p.y(), -p.z(), 0, p.x(), p.y(), -p.x(), 0;
  }

  double theta = kStrength;
  while (levels_.back().a.rows() > kCoarseUnknowns && levelCount() < kMaxLevels) {
    Level& fine = levels_.back();
    int count = 0;
    const std::vector<int> of = aggregate(fine.a, start, theta, count);
    const int nodes = static_cast<int>(start.size()) - 1;
    if (count >= nodes || count == 0) break;

    // nodes of every aggregate, in node order
    std::vector<int> members(static_cast<std::size_t>(nodes)), memberStart(count + 1, 0);
    for (int i = 0; i < nodes; ++i) ++memberStart[of[i] + 1];
    for (int c = 0; c < count; ++c) memberStart[c + 1] += memberStart[c];
    std::vector<int> fill(memberStart.begin(), memberStart.end() - 1);
    for (int i = 0; i < nodes; ++i) members[fill[of[i]]++] = i;

    // tentative prolongator: per aggregate, the orthonormal basis of its rigid motions
    std::vector<Eigen::Triplet<double>> entries;
    std::vector<int> coarseStart(1, 0);
    std::vector<Eigen::MatrixXd> coarseModes;
    for (int c = 0; c < count; ++c) {
      int rows = 0;
      for (int m = memberStart[c]; m < memberStart[c + 1]; ++m)
        rows += start[members[m] + 1] - start[members[m]];
      Eigen::MatrixXd local(rows, kModes);
      int row = 0;
      for (int m = memberStart[c]; m < memberStart[c + 1]; ++m)
        for (int d = start[members[m]]; d < start[members[m] + 1]; ++d) local.row(row++) = modes.row(d);
      Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(local);
      qr.setThreshold(1e-8);
      const int rank = std::max(1, static_cast<int>(qr.rank()));
      const Eigen::MatrixXd q = qr.householderQ() * Eigen::MatrixXd::Identity(rows, rank);
      Eigen::MatrixXd r = qr.matrixR().topRows(rank).triangularView<Eigen::Upper>();
      coarseModes.push_back(r * qr.colsPermutation().transpose());
      row = 0;
      for (int m = memberStart[c]; m < memberStart[c + 1]; ++m)
        for (int d = start[members[m]]; d < start[members[m] + 1]; ++d, ++row)
          for (int k = 0; k < rank; ++k) entries.emplace_back(d, coarseStart.back() + k, q(row, k));
      coarseStart.push_back(coarseStart.back() + rank);
    }
    RowMatrix tentative(fine.a.rows(), coarseStart.back());
    tentative.setFromTriplets(entries.begin(), entries.end());

    // smoothed prolongator and the Galerkin coarse matrix
    const double omega = 4.0 / (3.0 * spectralRadius(fine.a, fine.inverseDiagonal));
    RowMatrix ap = fine.a * tentative;
    RowMatrix correction = fine.inverseDiagonal.asDiagonal() * ap;
    correction *= omega;
    fine.p = tentative - correction;
    fine.r = fine.p.transpose();
    ap = fine.a * fine.p;
    Level next;
    next.a = fine.r * ap;
    next.inverseDiagonal = inverseDiagonalOf(next.a);

    modes.resize(coarseStart.back(), kModes);
    for (int c = 0; c < count; ++c) modes.middleRows(coarseStart[c], coarseStart[c + 1] - coarseStart[c]) = coarseModes[c];
    start = std::move(coarseStart);
    theta *= 0.5;
    levels_.push_back(std::move(next));
  }

  // the coarsest level: factored when small enough
  if (levels_.back().a.rows() <= kFactorLimit) {
    const Eigen::SparseMatrix<double> coarsest = levels_.back().a;
    factored_ = coarse_.compute(coarsest);
  }
  const std::size_t count = levels_.size();
  residual_.resize(count);
  coarseB_.resize(count);
  coarseX_.resize(count);
  return factored_ || levelCount() > 1;
}

void AggregationMultigrid::cycle(int level, const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  const Level& l = levels_[level];
  // coarsest: solve, or smooth when it could not be factored
  if (level + 1 == levelCount()) {
    if (factored_) {
      coarse_.solve(b, x);
    } else {
      x.setZero(b.size());
      gaussSeidel(l.a, l.inverseDiagonal, b, x, true);
      gaussSeidel(l.a, l.inverseDiagonal, b, x, false);
    }
    return;
  }
  // pre-smooth, restrict the residual, correct from below, post-smooth
  x.setZero(b.size());
  if (level == 0) {
    blockGaussSeidel(b, x, true);
    blockResidual(b, x, residual_[level]);
  } else {
    gaussSeidel(l.a, l.inverseDiagonal, b, x, true);
    residual_[level] = b - l.a * x;
  }
  coarseB_[level] = l.r * residual_[level];
  cycle(level + 1, coarseB_[level], coarseX_[level]);
  x += l.p * coarseX_[level];
  if (level == 0)
    blockGaussSeidel(b, x, false);
  else
    gaussSeidel(l.a, l.inverseDiagonal, b, x, false);
}

void AggregationMultigrid::blockGaussSeidel(const Eigen::VectorXd& b, Eigen::VectorXd& x,
                                            bool forward) const {
  const int n = static_cast<int>(fine_.start.size()) - 1;
  const int* start = fine_.start.data();
  const int* column = fine_.column.data();
  const double* value = fine_.value.data();
  double* xx = x.data();
  for (int k = 0; k < n; ++k) {
    const int i = forward ? k : n - 1 - k;
    double s0 = b[3 * i], s1 = b[3 * i + 1], s2 = b[3 * i + 2];
    for (int e = start[i]; e < start[i + 1]; ++e) {
      const double* m = value + 9 * e;
      const double* xj = xx + 3 * column[e];
      s0 -= m[0] * xj[0] + m[1] * xj[1] + m[2] * xj[2];
      s1 -= m[3] * xj[0] + m[4] * xj[1] + m[5] * xj[2];
      s2 -= m[6] * xj[0] + m[7] * xj[1] + m[8] * xj[2];
    }
    const double* d = fine_.inverseDiagonal.data() + 9 * i;
    xx[3 * i] += d[0] * s0 + d[1] * s1 + d[2] * s2;
    xx[3 * i + 1] += d[3] * s0 + d[4] * s1 + d[5] * s2;
    xx[3 * i + 2] += d[6] * s0 + d[7] * s1 + d[8] * s2;
  }
}

void AggregationMultigrid::blockResidual(const Eigen::VectorXd& b, const Eigen::VectorXd& x,
                                         Eigen::VectorXd& r) const {
  const int n = static_cast<int>(fine_.start.size()) - 1;
  r.resize(3 * n);
  const double* value = fine_.value.data();
  const double* xx = x.data();
  for (int i = 0; i < n; ++i) {
    double s0 = b[3 * i], s1 = b[3 * i + 1], s2 = b[3 * i + 2];
    for (int e = fine_.start[i]; e < fine_.start[i + 1]; ++e) {
      const double* m = value + 9 * e;
      const double* xj = xx + 3 * fine_.column[e];
      s0 -= m[0] * xj[0] + m[1] * xj[1] + m[2] * xj[2];
      s1 -= m[3] * xj[0] + m[4] * xj[1] + m[5] * xj[2];
      s2 -= m[6] * xj[0] + m[7] * xj[1] + m[8] * xj[2];
    }
    r[3 * i] = s0;
    r[3 * i + 1] = s1;
    r[3 * i + 2] = s2;
  }
}

void AggregationMultigrid::apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  if (levels_.empty()) {
    z.setZero(r.size());
    return;
  }
  if (levelCount() == 1 && !factored_) {
    const int n = static_cast<int>(jacobi_.size());
    z.resize(3 * n);
    for (int i = 0; i < n; ++i) z.segment<3>(3 * i) = jacobi_[i] * r.segment<3>(3 * i);
    return;
  }
  cycle(0, r, z);
}

}  // namespace microsim::sim::detail
