#include "solve/sparse_ldlt.h"

#include <Eigen/SparseCholesky>

namespace microsim::sim::detail {

struct SparseLdlt::Factors {
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> ldlt;
};

SparseLdlt::SparseLdlt() : factors_(std::make_unique<Factors>()) {}
SparseLdlt::~SparseLdlt() = default;
SparseLdlt::SparseLdlt(SparseLdlt&&) noexcept = default;
SparseLdlt& SparseLdlt::operator=(SparseLdlt&&) noexcept = default;

void SparseLdlt::analyzePattern(const Eigen::SparseMatrix<double>& lower) { factors_->ldlt.analyzePattern(lower); }

bool SparseLdlt::factorize(const Eigen::SparseMatrix<double>& lower) {
  factors_->ldlt.factorize(lower);
  return factors_->ldlt.info() == Eigen::Success;
}

bool SparseLdlt::compute(const Eigen::SparseMatrix<double>& lower) {
  analyzePattern(lower);
  return factorize(lower);
}

bool SparseLdlt::positiveDefinite() const { return (factors_->ldlt.vectorD().array() > 0.0).all(); }

void SparseLdlt::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const { x = factors_->ldlt.solve(b); }

}  // namespace microsim::sim::detail
