#include "solve/block_ldlt.h"

#include <Eigen/Cholesky>
#include <Eigen/OrderingMethods>
#include <Eigen/SparseCore>

#include <algorithm>

namespace microsim::sim::detail {

void BlockLdlt::analyze(const BlockSystem& a) {
  const int n = a.size();
  const auto offCount = static_cast<int>(a.off.size());
  size_ = n;
  pattern_.resize(a.off.size());
  for (int e = 0; e < offCount; ++e)
    pattern_[static_cast<std::size_t>(e)] = {a.off[static_cast<std::size_t>(e)].a,
                                             a.off[static_cast<std::size_t>(e)].b};

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
  position_.assign(static_cast<std::size_t>(n), 0);
  for (int k = 0; k < n; ++k)
    position_[static_cast<std::size_t>(order_[static_cast<std::size_t>(k)])] = k;

  // per column k of the ordered matrix, its entries above the diagonal
  columnStart_.assign(static_cast<std::size_t>(n) + 1, 0);
  selfEntries_.clear();
  for (const BlockSystem::Off& o : a.off)
    if (o.a != o.b)
      ++columnStart_[static_cast<std::size_t>(std::max(position_[static_cast<std::size_t>(o.a)],
                                                       position_[static_cast<std::size_t>(o.b)])) +
                     1];
  for (int k = 0; k < n; ++k)
    columnStart_[static_cast<std::size_t>(k) + 1] += columnStart_[static_cast<std::size_t>(k)];
  columnEntries_.resize(static_cast<std::size_t>(columnStart_.back()));
  std::vector<int> fill(columnStart_.begin(), columnStart_.end() - 1);
  for (int e = 0; e < offCount; ++e) {
    const BlockSystem::Off& o = a.off[static_cast<std::size_t>(e)];
    if (o.a == o.b) {
      selfEntries_.push_back(e);
      continue;
    }
    const int pa = position_[static_cast<std::size_t>(o.a)],
              pb = position_[static_cast<std::size_t>(o.b)];
    columnEntries_[static_cast<std::size_t>(fill[static_cast<std::size_t>(std::max(pa, pb))]++)] = {
        std::min(pa, pb), e};
  }

  // the elimination tree and the blocks of each column of L: from every A(i, k) up the tree
  // to a node row k reached already
  parent_.assign(static_cast<std::size_t>(n), -1);
  lCount_.assign(static_cast<std::size_t>(n), 0);
  flag_.assign(static_cast<std::size_t>(n), -1);
  for (int k = 0; k < n; ++k) {
    flag_[static_cast<std::size_t>(k)] = k;
    for (int c = columnStart_[static_cast<std::size_t>(k)];
         c < columnStart_[static_cast<std::size_t>(k) + 1]; ++c)
      for (int i = columnEntries_[static_cast<std::size_t>(c)].first;
           flag_[static_cast<std::size_t>(i)] != k; i = parent_[static_cast<std::size_t>(i)]) {
        if (parent_[static_cast<std::size_t>(i)] < 0) parent_[static_cast<std::size_t>(i)] = k;
        ++lCount_[static_cast<std::size_t>(i)];
        flag_[static_cast<std::size_t>(i)] = k;
      }
  }
  lStart_.assign(static_cast<std::size_t>(n) + 1, 0);
  for (int k = 0; k < n; ++k)
    lStart_[static_cast<std::size_t>(k) + 1] =
        lStart_[static_cast<std::size_t>(k)] + lCount_[static_cast<std::size_t>(k)];
  lRows_.resize(static_cast<std::size_t>(lStart_.back()));
  lValues_.resize(static_cast<std::size_t>(lStart_.back()));
  dInverse_.resize(static_cast<std::size_t>(n));
  y_.assign(static_cast<std::size_t>(n), Eigen::Matrix3d::Zero());
  stack_.resize(static_cast<std::size_t>(n));
}

bool BlockLdlt::factorize(const BlockSystem& a) {
  bool same = a.size() == size_ && a.off.size() == pattern_.size();
  for (std::size_t e = 0; same && e < a.off.size(); ++e)
    same = pattern_[e].first == a.off[e].a && pattern_[e].second == a.off[e].b;
  if (!same) analyze(a);
  const int n = size_;
  std::fill(flag_.begin(), flag_.end(), -1);
  std::fill(lCount_.begin(), lCount_.end(), 0);
  std::vector<Eigen::Matrix3d> selfBlocks(static_cast<std::size_t>(n), Eigen::Matrix3d::Zero());
  for (int e : selfEntries_) {
    const BlockSystem::Off& o = a.off[static_cast<std::size_t>(e)];
    selfBlocks[static_cast<std::size_t>(position_[static_cast<std::size_t>(o.a)])] +=
        2.0 * o.m.full();
  }

  for (int k = 0; k < n; ++k) {
    const std::size_t ks = static_cast<std::size_t>(k);
    Eigen::Matrix3d d = a.diag[static_cast<std::size_t>(order_[ks])] + selfBlocks[ks];

    // A(0:k, k) scattered into y, and the rows of L it reaches, in topological order
    int top = n;
    flag_[ks] = k;
    for (int c = columnStart_[ks]; c < columnStart_[ks + 1]; ++c) {
      const auto [row, e] = columnEntries_[static_cast<std::size_t>(c)];
      y_[static_cast<std::size_t>(row)] += a.off[static_cast<std::size_t>(e)].m.full();
      int length = 0;
      for (int i = row; flag_[static_cast<std::size_t>(i)] != k;
           i = parent_[static_cast<std::size_t>(i)]) {
        stack_[static_cast<std::size_t>(length++)] = i;
        flag_[static_cast<std::size_t>(i)] = k;
      }
      while (length > 0)
        stack_[static_cast<std::size_t>(--top)] = stack_[static_cast<std::size_t>(--length)];
    }

    // row k of L and the pivot block D(k)
    for (int t = top; t < n; ++t) {
      const std::size_t i = static_cast<std::size_t>(stack_[static_cast<std::size_t>(t)]);
      const Eigen::Matrix3d yi = y_[i];
      y_[i].setZero();
      const int begin = lStart_[i], end = begin + lCount_[i];
      for (int p = begin; p < end; ++p)
        y_[static_cast<std::size_t>(lRows_[static_cast<std::size_t>(p)])].noalias() -=
            lValues_[static_cast<std::size_t>(p)] * yi;
      const Eigen::Matrix3d lki = yi.transpose() * dInverse_[i];
      d.noalias() -= lki * yi;
      lRows_[static_cast<std::size_t>(end)] = k;
      lValues_[static_cast<std::size_t>(end)] = lki;
      ++lCount_[i];
    }
    const Eigen::LLT<Eigen::Matrix3d> pivot(0.5 * (d + d.transpose()));
    if (pivot.info() != Eigen::Success) {
      for (int t = top; t < n; ++t)
        y_[static_cast<std::size_t>(stack_[static_cast<std::size_t>(t)])].setZero();
      return false;
    }
    dInverse_[ks] = pivot.solve(Eigen::Matrix3d::Identity());
  }
  return true;
}

void BlockLdlt::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  const int n = size_;
  permuted_.resize(3 * n);
  for (int k = 0; k < n; ++k)
    permuted_.segment<3>(3 * k) = b.segment<3>(3 * order_[static_cast<std::size_t>(k)]);

  // L z = P b, then D w = z, then Lᵀ v = w
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d zi = permuted_.segment<3>(3 * i);
    for (int p = lStart_[static_cast<std::size_t>(i)]; p < lStart_[static_cast<std::size_t>(i) + 1];
         ++p)
      permuted_.segment<3>(3 * lRows_[static_cast<std::size_t>(p)]).noalias() -=
          lValues_[static_cast<std::size_t>(p)] * zi;
  }
  for (int i = 0; i < n; ++i)
    permuted_.segment<3>(3 * i) =
        dInverse_[static_cast<std::size_t>(i)] * permuted_.segment<3>(3 * i);
  for (int i = n - 1; i >= 0; --i) {
    Eigen::Vector3d vi = permuted_.segment<3>(3 * i);
    for (int p = lStart_[static_cast<std::size_t>(i)]; p < lStart_[static_cast<std::size_t>(i) + 1];
         ++p)
      vi.noalias() -= lValues_[static_cast<std::size_t>(p)].transpose() *
                      permuted_.segment<3>(3 * lRows_[static_cast<std::size_t>(p)]);
    permuted_.segment<3>(3 * i) = vi;
  }

  x.resize(3 * n);
  for (int k = 0; k < n; ++k)
    x.segment<3>(3 * order_[static_cast<std::size_t>(k)]) = permuted_.segment<3>(3 * k);
}

}  // namespace microsim::sim::detail
