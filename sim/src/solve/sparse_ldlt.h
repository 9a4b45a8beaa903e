#pragma once
// The sparse LDLᵀ factorisation of a symmetric matrix, read from its lower triangle (Eigen's
// SimplicialLDLT with its AMD ordering): the coarsest level of the multigrid. (Newton's direct
// path factorises by supernodes: supernodal_cholesky.h.)
//
// Why a class of its own. The factorisation and its triangular solves are most of a stitch
// replay's time. Under the sanitizer build (preset "sanitize": ASan, UBSan and libFuzzer's
// coverage) every memory access and comparison in Eigen's kernels is instrumented, and the
// kernels ran 25 times slower than in release: a third of the CI run went there. Kept behind
// this interface, Eigen's sparse Cholesky is instantiated in sparse_ldlt.cpp only, which that
// build compiles uninstrumented (sim/CMakeLists.txt); every caller stays checked, including
// the matrix it hands over and the solution it reads back.

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>

namespace microsim::sim::detail {

class SparseLdlt {
 public:
  SparseLdlt();
  ~SparseLdlt();
  SparseLdlt(SparseLdlt&&) noexcept;
  SparseLdlt& operator=(SparseLdlt&&) noexcept;
  SparseLdlt(const SparseLdlt&) = delete;
  SparseLdlt& operator=(const SparseLdlt&) = delete;

  /// The fill-reducing ordering and the factor's pattern for `lower`'s pattern; kept for
  /// every factorize of a matrix with the same pattern.
  void analyzePattern(const Eigen::SparseMatrix<double>& lower);
  /// Factorises `lower` (the pattern analysed last); false when it is singular.
  bool factorize(const Eigen::SparseMatrix<double>& lower);
  /// analyzePattern, then factorize.
  bool compute(const Eigen::SparseMatrix<double>& lower);
  /// Every pivot of D positive: the matrix factorised last is positive definite.
  [[nodiscard]] bool positiveDefinite() const;
  /// x = A⁻¹ b with the last factors.
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const;

 private:
  struct Factors;
  std::unique_ptr<Factors> factors_;
};

}  // namespace microsim::sim::detail
