#include "solve/supernodal_cholesky.h"

#include "solve/panel_kernels.h"

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCore>

#include <algorithm>

namespace microsim::sim::detail {
namespace {

/// Zero blocks a column of L may store so that its node joins its parent's supernode. Two pair
/// the tube's leaves (108 supernodes on the shipped stitch's Hessian instead of 188) and cut a
/// factorisation by 9 %; four cut it by 5 %, the zeros costing more than the fewer panels save.
constexpr int kRelaxedZeros = 2;

/// The elimination tree of the lower pattern given column by column (`above[k]`: the rows
/// i < k of column k), and the count of blocks below the diagonal in each column of L.
void eliminationTree(const std::vector<std::vector<int>>& above, std::vector<int>& parent,
                     std::vector<int>& count) {
  const int n = static_cast<int>(above.size());
  parent.assign(n, -1);
  count.assign(n, 0);
  std::vector<int> flag(n, -1);
  // from every A(i, k) up the tree to a node row k reached already: each one passed has
  // L(k, ·) in its column
  for (int k = 0; k < n; ++k) {
    flag[k] = k;
    for (int start : above[k])
      for (int i = start; flag[i] != k; i = parent[i]) {
        if (parent[i] < 0) parent[i] = k;
        ++count[i];
        flag[i] = k;
      }
  }
}

}  // namespace

void SupernodalCholesky::analyze(const BlockSystem& a) {
  ++analyses_;
  const int n = a.size();
  size_ = n;

  // the ordering: approximate minimum degree on the node graph
  // (Eigen's AMD needs the diagonal in the pattern: without it every order is kept as given)
  std::vector<Eigen::Triplet<double>> edges;
  edges.reserve(a.off.size() + static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) edges.emplace_back(i, i, 1.0);
  for (const BlockSystem::Off& o : a.off)
    if (o.a != o.b) edges.emplace_back(std::max(o.a, o.b), std::min(o.a, o.b), 1.0);
  Eigen::SparseMatrix<double> graph(n, n);
  graph.setFromTriplets(edges.begin(), edges.end());
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> amd;
  Eigen::AMDOrdering<int>()(graph, amd);
  order_.assign(amd.indices().data(), amd.indices().data() + n);
  position_.resize(n);
  for (int k = 0; k < n; ++k) position_[order_[k]] = k;

  // the tree and the columns' counts
  std::vector<std::vector<int>> above(n);
  for (const BlockSystem::Off& o : a.off)
    if (o.a != o.b) {
      const int pa = position_[o.a], pb = position_[o.b];
      above[std::max(pa, pb)].push_back(std::min(pa, pb));
    }
  std::vector<int> parent, count;
  eliminationTree(above, parent, count);

  // the supernodes, from the last column back: k joins k + 1's when k + 1 is its parent and
  // its column then stores at most kRelaxedZeros zero blocks (its rows: the supernode's
  // columns after it and the rows below the supernode)
  std::vector<int> zeros(n, 0);
  std::vector<char> joins(n, 0);
  for (int k = n - 2; k >= 0; --k) {
    const int stored = count[k + 1] + zeros[k + 1] + 1;
    if (parent[k] == k + 1 && stored - count[k] <= kRelaxedZeros) {
      joins[k] = 1;
      zeros[k] = stored - count[k];
    }
  }
  superStart_.assign(1, 0);
  for (int k = 1; k < n; ++k)
    if (!joins[k - 1]) superStart_.push_back(k);
  if (n > 0) superStart_.push_back(n);
  const int supernodes = static_cast<int>(superStart_.size()) - 1;
  superOf_.assign(n, 0);
  for (int s = 0; s < supernodes; ++s)
    std::fill(superOf_.begin() + superStart_[s], superOf_.begin() + superStart_[s + 1], s);

  // each supernode's rows below it: those of its last column, found by the tree walk again
  rowStart_.assign(supernodes + 1, 0);
  for (int s = 0; s < supernodes; ++s)
    rowStart_[s + 1] = rowStart_[s] + count[superStart_[s + 1] - 1];
  rows_.resize(rowStart_.back());
  std::vector<int> fill(rowStart_.begin(), rowStart_.end() - 1), flag(n, -1);
  for (int k = 0; k < n; ++k) {
    flag[k] = k;
    for (int start : above[k])
      for (int i = start; flag[i] != k; i = parent[i]) {
        flag[i] = k;
        const int s = superOf_[i];
        if (i == superStart_[s + 1] - 1) rows_[fill[s]++] = k;
      }
  }

  // the panels, and where every entry of A lands
  valueStart_.assign(supernodes + 1, 0);
  factorBlocks_ = 0;
  for (int s = 0; s < supernodes; ++s) {
    const int w = superStart_[s + 1] - superStart_[s], r = rowStart_[s + 1] - rowStart_[s];
    valueStart_[s + 1] = valueStart_[s] + 9 * w * (w + r);
    factorBlocks_ += w * (w - 1) / 2 + w * r;
  }
  values_.resize(valueStart_.back());
  inverseDiagonal_.resize(3 * static_cast<std::size_t>(n));
  rowInTarget_.assign(n, 0);
  diagonalOffset_.resize(n);
  for (int k = 0; k < n; ++k) diagonalOffset_[k] = offsetOf(k, k);
  placeEntries(a);
}

bool SupernodalCholesky::placeEntries(const BlockSystem& a) {
  entryOffset_.resize(a.off.size());
  for (std::size_t e = 0; e < a.off.size(); ++e) {
    const int pa = position_[a.off[e].a], pb = position_[a.off[e].b];
    const int column = std::min(pa, pb), s = superOf_[column];
    entryOffset_[e] = {offsetOf(std::max(pa, pb), column),
                       3 * (superStart_[s + 1] - superStart_[s])};
    if (entryOffset_[e].first < 0) return false;
  }
  return true;
}

int SupernodalCholesky::offsetOf(int row, int column) const {
  const int s = superOf_[column], first = superStart_[s], w = superStart_[s + 1] - first;
  int slice = row - first;
  if (row >= first + w) {
    const auto below = rows_.begin() + rowStart_[s], end = rows_.begin() + rowStart_[s + 1];
    const auto at = std::lower_bound(below, end, row);
    if (at == end || *at != row) return -1;
    slice = w + static_cast<int>(at - below);
  }
  return valueStart_[s] + 9 * w * slice + 3 * (column - first);
}

bool SupernodalCholesky::factorize(const BlockSystem& a) {
  bool same = a.size() == size_ && a.off.size() == pattern_.size();
  for (std::size_t e = 0; same && e < a.off.size(); ++e)
    same = pattern_[e].first == a.off[e].a && pattern_[e].second == a.off[e].b;
  if (!same) {
    // a pattern the kept structure covers keeps the ordering and analysis, only its entries
    // move: terms dropped, or added between nodes L couples already (6 of the shipped
    // stitch's 10 new patterns; an analysis costs 0.35 ms there, two thirds of a factorisation)
    if (a.size() != size_ || !placeEntries(a)) analyze(a);
    pattern_.clear();
    for (const BlockSystem::Off& o : a.off) pattern_.emplace_back(o.a, o.b);
  }

  // A into the panels: the diagonal blocks' lower triangles and the blocks below them (an
  // entry with both ends on one node adds twice to its diagonal block)
  std::fill(values_.begin(), values_.end(), 0.0);
  const auto add = [&](int offset, int ld, const Eigen::Matrix3d& m) {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) values_[offset + r * ld + c] += m(r, c);
  };
  for (int k = 0; k < size_; ++k)
    add(diagonalOffset_[k], 3 * (superStart_[superOf_[k] + 1] - superStart_[superOf_[k]]),
        a.diag[order_[k]]);
  for (std::size_t e = 0; e < a.off.size(); ++e) {
    const BlockSystem::Off& o = a.off[e];
    add(entryOffset_[e].first, entryOffset_[e].second,
        o.a == o.b ? Eigen::Matrix3d(2.0 * o.m.full()) : o.m.full());
  }

  const int supernodes = static_cast<int>(superStart_.size()) - 1;
  for (int s = 0; s < supernodes; ++s) {
    if (!factorPanel(s)) return false;
    updateLater(s);
  }
  return true;
}

bool SupernodalCholesky::factorPanel(int s) {
  const int first = superStart_[s], w = superStart_[s + 1] - first;
  const int slices = w + rowStart_[s + 1] - rowStart_[s], ld = 3 * w;
  double* p = values_.data() + valueStart_[s];
  double* inverse = inverseDiagonal_.data() + 3 * first;
  // one node column at a time: its pivot block, then the blocks below it (independent of
  // each other), each less the products of the columns before it
  for (int j = 0; j < w; ++j) {
    const double* column = p + 3 * j * ld;
    double* pivot = p + 3 * j * ld + 3 * j;
    if (j > 0) panel::subtractProduct(column, column, ld, 3 * j, pivot, ld);
    if (!panel::factorPivot(pivot, ld, inverse + 3 * j)) return false;
    for (int i = j + 1; i < slices; ++i) {
      double* block = p + 3 * i * ld + 3 * j;
      if (j > 0) panel::subtractProduct(p + 3 * i * ld, column, ld, 3 * j, block, ld);
      panel::solveAgainstPivot(pivot, inverse + 3 * j, block, ld);
    }
  }
  return true;
}

void SupernodalCholesky::updateLater(int s) {
  const int w = superStart_[s + 1] - superStart_[s], ld = 3 * w;
  const int r0 = rowStart_[s], r = rowStart_[s + 1] - r0;
  const double* below = values_.data() + valueStart_[s] + 9 * w * w;
  int target = -1;
  for (int q = 0; q < r; ++q) {
    // column rows_[r0 + q] lies in supernode t: where t's rows are
    const int column = rows_[r0 + q], t = superOf_[column];
    const int tFirst = superStart_[t], tw = superStart_[t + 1] - tFirst;
    if (t != target) {
      target = t;
      for (int i = 0; i < tw; ++i) rowInTarget_[tFirst + i] = i;
      for (int i = rowStart_[t]; i < rowStart_[t + 1]; ++i)
        rowInTarget_[rows_[i]] = tw + i - rowStart_[t];
    }
    double* into = values_.data() + valueStart_[t] + 3 * (column - tFirst);
    for (int p = q; p < r; ++p)
      panel::subtractProduct(below + 3 * p * ld, below + 3 * q * ld, ld, ld,
                             into + 9 * tw * rowInTarget_[rows_[r0 + p]], 3 * tw);
  }
}

void SupernodalCholesky::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  const int n = size_, supernodes = static_cast<int>(superStart_.size()) - 1;
  permuted_.resize(3 * n);
  for (int k = 0; k < n; ++k) permuted_.segment<3>(3 * k) = b.segment<3>(3 * order_[k]);
  double* v = permuted_.data();

  // L z = P b, supernode by supernode: its own rows, then what they take from the rows below
  for (int s = 0; s < supernodes; ++s) {
    const int first = superStart_[s], w = superStart_[s + 1] - first, ld = 3 * w;
    const int r0 = rowStart_[s], r = rowStart_[s + 1] - r0;
    const double* p = values_.data() + valueStart_[s];
    const double* inverse = inverseDiagonal_.data() + 3 * first;
    double* own = v + 3 * first;
    for (int i = 0; i < w; ++i) {
      const double* slice = p + 3 * i * ld;
      panel::subtractSliceTimes(slice, ld, own, 3 * i, own + 3 * i);
      panel::forwardPivot(slice + 3 * i, ld, inverse + 3 * i, own + 3 * i);
    }
    for (int q = 0; q < r; ++q)
      panel::subtractSliceTimes(p + (ld + 3 * q) * ld, ld, own, ld, v + 3 * rows_[r0 + q]);
  }

  // Lᵀ P x = z, supernode by supernode backwards: the rows below first, then its own
  for (int s = supernodes - 1; s >= 0; --s) {
    const int first = superStart_[s], w = superStart_[s + 1] - first, ld = 3 * w;
    const int r0 = rowStart_[s], r = rowStart_[s + 1] - r0;
    const double* p = values_.data() + valueStart_[s];
    const double* inverse = inverseDiagonal_.data() + 3 * first;
    double* own = v + 3 * first;
    sums_.assign(ld, 0.0);
    for (int q = 0; q < r; ++q)
      panel::addSliceTransposedTimes(p + (ld + 3 * q) * ld, ld, v + 3 * rows_[r0 + q], ld,
                                     sums_.data());
    for (int i = w - 1; i >= 0; --i) {
      const double* slice = p + 3 * i * ld;
      panel::backwardPivot(slice + 3 * i, ld, inverse + 3 * i, sums_.data() + 3 * i, own + 3 * i);
      panel::addSliceTransposedTimes(slice, ld, own + 3 * i, 3 * i, sums_.data());
    }
  }

  x.resize(3 * n);
  for (int k = 0; k < n; ++k) x.segment<3>(3 * order_[k]) = permuted_.segment<3>(3 * k);
}

}  // namespace microsim::sim::detail
