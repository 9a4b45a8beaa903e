#pragma once
// A sparse symmetric system in 3 by 3 blocks over a set of nodes, as the implicit and
// Newton solvers build it: one diagonal block per unknown node and one off-diagonal block
// per link whose two ends are both unknowns. Matrix-free in spirit: the blocks are the
// only storage, the product walks them once, and the block-Jacobi preconditioned CG
// needs nothing else.

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <vector>

namespace microsim::sim::detail {

/// A symmetric 3 by 3 block in 6 numbers (xx, xy, xz, yy, yz, zz).
struct SymBlock {
  double xx = 0, xy = 0, xz = 0, yy = 0, yz = 0, zz = 0;

  static SymBlock from(const Eigen::Matrix3d& m) {
    return {m(0, 0), m(0, 1), m(0, 2), m(1, 1), m(1, 2), m(2, 2)};
  }
  Eigen::Matrix3d full() const {
    Eigen::Matrix3d m;
    m << xx, xy, xz, xy, yy, yz, xz, yz, zz;
    return m;
  }
};

struct BlockSystem {
  struct Off {
    int a = 0;  ///< local index of one end
    int b = 0;  ///< local index of the other
    SymBlock m;  ///< the block at (a, b) and (b, a)
  };
  std::vector<Eigen::Matrix3d> diag;  ///< one per unknown node
  std::vector<Off> off;

  int size() const { return static_cast<int>(diag.size()); }
  void clear(int nodes) {
    diag.assign(static_cast<std::size_t>(nodes), Eigen::Matrix3d::Zero());
    off.clear();
  }
  /// y = A p (both 3·size()).
  void multiply(const Eigen::VectorXd& p, Eigen::VectorXd& y) const;
  /// The same matrix as a scalar row-major sparse matrix (3·size() square), columns
  /// sorted within each row.
  Eigen::SparseMatrix<double, Eigen::RowMajor> toSparse() const;
};

/// z = M⁻¹ r for a symmetric positive definite M ≈ A, as PCG needs it.
class Preconditioner {
 public:
  virtual ~Preconditioner() = default;
  virtual void apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const = 0;
};

/// M = the block diagonal of A (each 3 by 3 block inverted once).
class BlockJacobi final : public Preconditioner {
 public:
  explicit BlockJacobi(const BlockSystem& a);
  void apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) const override;

 private:
  std::vector<Eigen::Matrix3d> inverse_;
};

struct PcgResult {
  int iterations = 0;
  double relativeResidual = 0.0;  ///< |b − A x| / |b| at the end
  bool ok = true;                 ///< false on a breakdown (non-positive curvature, NaN)
};

/// Preconditioned conjugate gradients for A x = b from x = 0, until |r| ≤ tolerance·|b|
/// or maxIterations.
PcgResult solvePcg(const BlockSystem& a, const Preconditioner& m, const Eigen::VectorXd& b,
                   Eigen::VectorXd& x, double tolerance, int maxIterations);
/// The same with the block-Jacobi preconditioner.
PcgResult solvePcg(const BlockSystem& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                   double tolerance, int maxIterations);

/// Inverse of a diagonal block, regularised when (near) singular.
Eigen::Matrix3d invertBlock(const Eigen::Matrix3d& m);

}  // namespace microsim::sim::detail
