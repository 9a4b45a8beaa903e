// The block LDLᵀ factorisation: its solves against a dense solve of the same matrix, a pattern
// that changes between factorisations, entries repeated on one pair of nodes, and a matrix that
// is not positive definite.
#include "solve/block_ldlt.h"
#include "solve/block_system.h"

#include <Eigen/Cholesky>

#include <gtest/gtest.h>

#include <random>

namespace microsim::sim::detail {
namespace {

/// A random symmetric block matrix, diagonally dominant (so positive definite) unless
/// `shift` takes it below zero: `nodes` nodes, about `degree` neighbours each, some pairs twice.
/// The dense matrix of `a`, column by column from its product (repeated pairs add up).
Eigen::MatrixXd denseOf(const BlockSystem& a) {
  const Eigen::Index n = 3 * a.size();
  Eigen::MatrixXd dense(n, n);
  Eigen::VectorXd column;
  for (Eigen::Index c = 0; c < n; ++c) {
    a.multiply(Eigen::VectorXd::Unit(n, c), column);
    dense.col(c) = column;
  }
  return dense;
}

BlockSystem randomSystem(int nodes, int degree, unsigned seed, double shift = 0.0) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::uniform_int_distribution<int> node(0, nodes - 1);
  BlockSystem a;
  a.clear(nodes);
  for (int e = 0; e < nodes * degree / 2; ++e) {
    const int i = node(random), j = node(random);
    if (i == j) continue;
    Eigen::Matrix3d m;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) m(r, c) = value(random);
    m = 0.5 * (m + m.transpose()).eval();
    a.off.push_back({i, j, SymBlock::from(m)});
    // a repeated pair, as a link and a soft term on the same two nodes give
    if (e % 7 == 0) a.off.push_back({j, i, SymBlock::from(0.5 * m)});
  }
  const Eigen::MatrixXd dense = denseOf(a);
  for (int i = 0; i < nodes; ++i) {
    double row = 0.0;
    for (int r = 0; r < 3; ++r) row = std::max(row, dense.row(3 * i + r).cwiseAbs().sum());
    a.diag[static_cast<std::size_t>(i)] += (3.0 * row + 1.0 + shift) * Eigen::Matrix3d::Identity();
  }
  return a;
}

Eigen::VectorXd denseSolve(const BlockSystem& a, const Eigen::VectorXd& b) {
  return denseOf(a).ldlt().solve(b);
}

TEST(BlockLdlt, SolvesAsTheDenseFactorisation) {
  const BlockSystem a = randomSystem(60, 6, 1);
  BlockLdlt ldlt;
  ASSERT_TRUE(ldlt.factorize(a));
  std::mt19937 random(2);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  Eigen::VectorXd b(3 * a.size());
  for (Eigen::Index i = 0; i < b.size(); ++i) b[i] = value(random);
  Eigen::VectorXd x;
  ldlt.solve(b, x);
  EXPECT_LT((x - denseSolve(a, b)).norm(), 1e-10 * x.norm());
  EXPECT_GT(ldlt.factorBlocks(), 0);
}

TEST(BlockLdlt, FollowsAChangedPatternAndNewValues) {
  BlockLdlt ldlt;
  const BlockSystem first = randomSystem(40, 4, 3);
  ASSERT_TRUE(ldlt.factorize(first));
  // other values on the same pattern, then another pattern and size
  BlockSystem second = first;
  for (Eigen::Matrix3d& d : second.diag) d *= 1.5;
  const BlockSystem third = randomSystem(50, 8, 4);
  for (const BlockSystem* a : {static_cast<const BlockSystem*>(&second), &third}) {
    ASSERT_TRUE(ldlt.factorize(*a));
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(3 * a->size(), -1.0, 2.0);
    Eigen::VectorXd x;
    ldlt.solve(b, x);
    EXPECT_LT((x - denseSolve(*a, b)).norm(), 1e-10 * x.norm());
  }
}

TEST(BlockLdlt, RefusesAnIndefiniteMatrix) {
  BlockSystem a = randomSystem(30, 4, 5);
  a.diag[17](1, 1) = -1e3;
  BlockLdlt ldlt;
  EXPECT_FALSE(ldlt.factorize(a));
  // and factorises again once it is definite
  a.diag[17](1, 1) = 1e3;
  EXPECT_TRUE(ldlt.factorize(a));
}

}  // namespace
}  // namespace microsim::sim::detail
