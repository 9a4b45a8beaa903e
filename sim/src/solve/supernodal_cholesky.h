#pragma once
// The sparse Cholesky factorisation of a BlockSystem, supernodal: A = P L Lᵀ Pᵀ with L lower
// triangular and P a fill-reducing ordering of the nodes (approximate minimum degree on the node
// graph, each node's x, y, z kept together). Newton's direct path on small regions factorises
// with it, and preconditions CG with the factors it keeps.
//
// Supernodes. Consecutive columns of L whose rows below them are the same (a node, its parent in
// the elimination tree, its parent's parent, ... while each adds one row) are stored and worked
// on together, as one dense panel: the supernode's columns by the rows they reach, row-major.
// A node also joins its parent's supernode when that stores at most kRelaxedZeros blocks of
// zeros in its column ("relaxed" supernodes: the tube's leaves pair up). Then the work is dense
// products of 3-row slices (panel_kernels.h), each index loaded once for a whole row of
// numbers, where a node-by-node factorisation in 3 by 3 blocks loaded one for every 9.
//
// The algorithm (right-looking by supernodes, Davis, "Direct Methods for Sparse Linear
// Systems", SIAM 2006, ch. 9; Liu, Ng and Peyton 1993 for the supernodes):
//  - analysis: the elimination tree of P A Pᵀ and the count of blocks in each column of L, from
//    every A(i, k) (i < k) up the tree to a node row k reached already (Davis ch. 4); the
//    supernodes; each one's rows below it, by the same walk; where every entry of A lands;
//  - numbers, supernode by supernode in order: the panel holds A's entries minus what earlier
//    supernodes subtracted; its own columns are factorised (dense Cholesky of the diagonal
//    block, the rows below solved against it, one node column at a time); then it subtracts
//    B Bᵀ (B: its rows below) from the later panels those rows belong to.
// A pivot that is not positive stops the factorisation: the matrix is not positive definite.
//
// Measured on the shipped stitch's Hessian (all 384 free nodes of resources/scenes/
// anastomosis.json, links at 2 % strain; 108 supernodes, two of them the tubes' 42-node top
// separators; 7664 blocks in L against 7504 node by node): a factorisation takes 0.51–0.56 ms
// against 0.87 ms for the node-by-node LDLᵀ in 3 by 3 blocks it replaced, a solve 0.037–0.041 ms
// against 0.052 ms (thread CPU, best of 30 rounds of 50 factorisations and 200 solves, on a
// busy 2-core machine); callgrind: 8.5 M instructions against 12.3 M a factorisation, 0.49 M
// against 0.61 M a solve. The products are pairs of doubles bound by the multiplier and adder
// ports, not by the instruction count. Over the stitch (`microsim-cli bench scene --quick`,
// alternated with the build before) the step's p99 went from 3.2–3.5 ms to 2.3–2.6 ms with the
// contact and stretch-check changes of the same series, the median from 0.82 to 0.65 ms.
//
// Kept in one unit of its own, as sparse_ldlt.h explains: the sanitizer build compiles it
// uninstrumented (sim/CMakeLists.txt); its callers stay checked.

#include "solve/block_system.h"

#include <Eigen/Core>

#include <utility>
#include <vector>

namespace microsim::sim::detail {

class SupernodalCholesky {
 public:
  /// Factorises `a`; false when `a` is not positive definite. The ordering and analysis are
  /// kept while the size stays and every off-diagonal entry lands within the kept factor's
  /// structure (a pattern that lost terms, or gained some between nodes already coupled in L).
  bool factorize(const BlockSystem& a);
  /// x = A⁻¹ b with the last factors (both 3·size()).
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const;
  /// 3 by 3 blocks stored below the diagonal of L (after factorize), zeros of the relaxed
  /// supernodes included.
  [[nodiscard]] int factorBlocks() const { return factorBlocks_; }
  /// Analyses done so far.
  [[nodiscard]] int analyses() const { return analyses_; }

 private:
  void analyze(const BlockSystem& a);
  /// Where every off-diagonal entry of `a` lands in values_ (entryOffset_); false when one
  /// falls outside the factor's structure.
  bool placeEntries(const BlockSystem& a);
  /// Factorises supernode s's panel; false at a pivot that is not positive.
  bool factorPanel(int s);
  /// Subtracts supernode s's B Bᵀ from the later panels.
  void updateLater(int s);
  /// Where row `row` of column `column` (positions, row ≥ column) lands in values_, −1 when
  /// outside the structure.
  [[nodiscard]] int offsetOf(int row, int column) const;

  // the pattern factorised last, and the ordering: position → node and back
  std::vector<std::pair<int, int>> pattern_;
  int size_ = -1;
  std::vector<int> order_, position_;
  // supernode s: positions superStart_[s] .. superStart_[s + 1] − 1; its rows below them,
  // ascending, rows_[rowStart_[s] ..]; its panel at values_[valueStart_[s]]
  std::vector<int> superStart_, superOf_, rowStart_, rows_, valueStart_;
  // where A lands: per position its diagonal block, per off entry its block (and that
  // panel's row length)
  std::vector<int> diagonalOffset_;
  std::vector<std::pair<int, int>> entryOffset_;
  std::vector<double> values_, inverseDiagonal_;
  int factorBlocks_ = 0, analyses_ = 0;
  // scratch: a target panel's row of each position; the solves' work vectors
  std::vector<int> rowInTarget_;
  mutable Eigen::VectorXd permuted_;
  mutable std::vector<double> sums_;
};

}  // namespace microsim::sim::detail
