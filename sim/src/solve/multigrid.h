#pragma once
// Smoothed-aggregation algebraic multigrid (Vaněk, Mandel, Brezina 1996) as the
// preconditioner of Newton's conjugate gradients on big regions.
//
// Why. Block-Jacobi CG needs O(n) iterations on an n³ box, because the error a pull
// leaves is smooth (the 1/r far field) and a local preconditioner only damps what is
// rough. A direct factorisation does not fit the frame either: on 20³ (22,800 unknowns)
// the Cholesky factor has ~10⁷ entries, seconds to compute and tens of ms to apply.
// Multigrid removes the smooth error on coarse copies of the mesh, so CG converges in a
// number of iterations that hardly depends on the size or on the stiffness ratio.
//
// The hierarchy. Level 0 is the system A (3 unknowns per node). Each level groups its
// nodes into aggregates: a node with its strongly coupled neighbours,
// ‖A_ij‖_F ≥ θ √(‖A_ii‖_F ‖A_jj‖_F), so that a stiff part is never lumped with a soft
// one. The tentative prolongator P̂ maps one coarse node per aggregate onto its fine nodes
// so that it reproduces the rigid motions B (3 translations and 3 rotations about the
// region's centroid): per aggregate B_agg = Q R (column-pivoted QR, rank-revealing),
// P̂ = Q and the coarse node's rows of the coarse B are R. The prolongator is then
// smoothed, P = (I − ω D⁻¹ A) P̂ with ω = 4 / (3 ρ(D⁻¹ A)), D = diag(A), ρ estimated
// by power iteration, and the coarse system is A_c = Pᵀ A P (Galerkin). Levels are added
// until a level is small enough to factor (sparse LDLᵀ).
//
// One application is a symmetric V-cycle from z = 0: forward Gauss–Seidel, restriction
// of the residual, the coarser level, prolongation, backward Gauss–Seidel. Symmetric and
// positive definite when A is, as CG requires. Building costs a few dozen products of
// A with a vector; Newton keeps one hierarchy over many iterations and cycles as the
// preconditioner of the current Hessian and rebuilds it only when CG slows down.
// Deterministic: every loop runs in index order.

#include "solve/block_system.h"
#include "solve/sparse_ldlt.h"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <vector>

namespace microsim::sim::detail {

class AggregationMultigrid final : public Preconditioner {
 public:
  using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

  /// Builds the hierarchy for `a`, whose unknown node r sits at positions.col(r) (mm;
  /// 3 by a.size()). False when the coarsest level could not be factored (then apply
  /// falls back to block Jacobi on level 0).
  bool build(const BlockSystem& a, const Eigen::Matrix3Xd& positions);
  void apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const override;

  int levelCount() const { return static_cast<int>(levels_.size()); }
  /// Unknowns of level `level` (0 = the fine system).
  int unknowns(int level) const { return static_cast<int>(levels_[level].a.rows()); }
  /// Stored entries of level `level`'s matrix.
  long nonZeros(int level) const { return static_cast<long>(levels_[level].a.nonZeros()); }

 private:
  struct Level {
    RowMatrix a;                  ///< this level's matrix
    Eigen::VectorXd inverseDiagonal;
    RowMatrix p;                  ///< prolongation from the next level (empty on the last)
    RowMatrix r;                  ///< restriction pᵀ
  };

  /// Level 0 again, as rows of 3 by 3 node blocks (9 numbers each, row-major), for a
  /// block Gauss–Seidel smoother that is both stronger and cheaper than the scalar one.
  struct BlockRows {
    std::vector<int> start;  ///< blocks of node i: [start[i], start[i + 1])
    std::vector<int> column;  ///< node of each block
    std::vector<double> value;
    std::vector<double> inverseDiagonal;  ///< 9 per node
  };

  void cycle(int level, const Eigen::VectorXd& b, Eigen::VectorXd& x) const;
  void blockGaussSeidel(const Eigen::VectorXd& b, Eigen::VectorXd& x, bool forward) const;
  void blockResidual(const Eigen::VectorXd& b, const Eigen::VectorXd& x, Eigen::VectorXd& r) const;

  std::vector<Level> levels_;
  BlockRows fine_;
  SparseLdlt coarse_;
  bool factored_ = false;
  std::vector<Eigen::Matrix3d> jacobi_;  ///< level-0 fallback
  mutable std::vector<Eigen::VectorXd> residual_, coarseB_, coarseX_;
};

}  // namespace microsim::sim::detail
