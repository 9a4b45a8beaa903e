// The supernodal Cholesky factorisation: its solves against a dense solve of the same matrix
// (random patterns and a tube's, whose supernodes are wide), a pattern that changes between
// factorisations (and one that does not, which keeps its analysis), entries repeated on one pair
// of nodes, and a matrix that is not positive definite.
#include "solve/supernodal_cholesky.h"
#include "solve/block_system.h"

#include <Eigen/Cholesky>

#include <gtest/gtest.h>

#include <random>

namespace microsim::sim::detail {
namespace {

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

/// A random symmetric 3 by 3 block.
Eigen::Matrix3d randomBlock(std::mt19937& random) {
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  Eigen::Matrix3d m;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m(r, c) = value(random);
  return 0.5 * (m + m.transpose());
}

/// Makes `a` diagonally dominant (so positive definite) unless `shift` takes it below zero.
void dominate(BlockSystem& a, double shift) {
  const Eigen::MatrixXd dense = denseOf(a);
  for (int i = 0; i < a.size(); ++i) {
    double row = 0.0;
    for (int r = 0; r < 3; ++r) row = std::max(row, dense.row(3 * i + r).cwiseAbs().sum());
    a.diag[static_cast<std::size_t>(i)] += (3.0 * row + 1.0 + shift) * Eigen::Matrix3d::Identity();
  }
}

/// A random symmetric block matrix: `nodes` nodes, about `degree` neighbours each, some pairs
/// twice.
BlockSystem randomSystem(int nodes, int degree, unsigned seed, double shift = 0.0) {
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> node(0, nodes - 1);
  BlockSystem a;
  a.clear(nodes);
  for (int e = 0; e < nodes * degree / 2; ++e) {
    const int i = node(random), j = node(random);
    if (i == j) continue;
    const Eigen::Matrix3d m = randomBlock(random);
    a.off.push_back({i, j, SymBlock::from(m)});
    // a repeated pair, as a link and a soft term on the same two nodes give
    if (e % 7 == 0) a.off.push_back({j, i, SymBlock::from(0.5 * m)});
  }
  dominate(a, shift);
  return a;
}

/// The pattern of a vessel's wall, as the scenes mesh it: `rings` rings of `around` nodes in
/// two layers, each node linked to its neighbours around the ring, along the tube (straight and
/// diagonally) and across the wall; random values.
BlockSystem tubeSystem(int rings, int around, unsigned seed) {
  std::mt19937 random(seed);
  const auto node = [&](int ring, int k, int layer) {
    return (ring * around + (k + around) % around) * 2 + layer;
  };
  BlockSystem a;
  a.clear(rings * around * 2);
  for (int ring = 0; ring < rings; ++ring)
    for (int k = 0; k < around; ++k)
      for (int layer = 0; layer < 2; ++layer) {
        const int i = node(ring, k, layer);
        a.off.push_back({i, node(ring, k + 1, layer), SymBlock::from(randomBlock(random))});
        if (layer == 0) a.off.push_back({i, node(ring, k, 1), SymBlock::from(randomBlock(random))});
        if (ring + 1 < rings) {
          a.off.push_back({i, node(ring + 1, k, layer), SymBlock::from(randomBlock(random))});
          a.off.push_back({i, node(ring + 1, k + 1, layer), SymBlock::from(randomBlock(random))});
        }
      }
  dominate(a, 0.0);
  return a;
}

Eigen::VectorXd randomVector(Eigen::Index size, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  Eigen::VectorXd b(size);
  for (Eigen::Index i = 0; i < b.size(); ++i) b[i] = value(random);
  return b;
}

void expectSolvesAsDense(const SupernodalCholesky& factors, const BlockSystem& a, unsigned seed) {
  const Eigen::VectorXd b = randomVector(3 * a.size(), seed);
  Eigen::VectorXd x;
  factors.solve(b, x);
  const Eigen::VectorXd reference = denseOf(a).ldlt().solve(b);
  EXPECT_LT((x - reference).norm(), 1e-10 * reference.norm());
}

TEST(SupernodalCholesky, SolvesAsTheDenseFactorisation) {
  const BlockSystem a = randomSystem(60, 6, 1);
  SupernodalCholesky factors;
  ASSERT_TRUE(factors.factorize(a));
  expectSolvesAsDense(factors, a, 2);
  EXPECT_GT(factors.factorBlocks(), 0);
}

TEST(SupernodalCholesky, SolvesATubesPatternAsTheDenseFactorisation) {
  // two vessel ends, unconnected, as the shipped scene's free nodes (6 rings of 16, two layers)
  BlockSystem a = tubeSystem(6, 16, 3);
  const BlockSystem other = tubeSystem(6, 16, 4);
  const int offset = a.size();
  a.diag.insert(a.diag.end(), other.diag.begin(), other.diag.end());
  for (BlockSystem::Off o : other.off) {
    o.a += offset;
    o.b += offset;
    a.off.push_back(o);
  }
  SupernodalCholesky factors;
  ASSERT_TRUE(factors.factorize(a));
  expectSolvesAsDense(factors, a, 5);
  // the fill: more blocks than A has below its diagonal, fewer than a dense factor
  EXPECT_GT(factors.factorBlocks(), static_cast<int>(a.off.size()));
  EXPECT_LT(factors.factorBlocks(), a.size() * (a.size() - 1) / 4);
}

TEST(SupernodalCholesky, FollowsAChangedPatternAndNewValues) {
  SupernodalCholesky factors;
  const BlockSystem first = randomSystem(40, 4, 3);
  ASSERT_TRUE(factors.factorize(first));
  EXPECT_EQ(factors.analyses(), 1);
  // other values on the same pattern (the analysis kept), then another pattern and size
  BlockSystem second = first;
  for (Eigen::Matrix3d& d : second.diag) d *= 1.5;
  for (BlockSystem::Off& o : second.off) o.m = SymBlock::from(0.5 * o.m.full());
  ASSERT_TRUE(factors.factorize(second));
  EXPECT_EQ(factors.analyses(), 1);
  expectSolvesAsDense(factors, second, 6);
  const BlockSystem third = randomSystem(50, 8, 4);
  ASSERT_TRUE(factors.factorize(third));
  EXPECT_EQ(factors.analyses(), 2);
  expectSolvesAsDense(factors, third, 7);
}

TEST(SupernodalCholesky, KeepsTheAnalysisForAPatternWithinItsFactor) {
  // a tube with a soft term between two nodes across it, then without it (the factor's
  // structure covers that), then with one between nodes the factor does not couple yet
  BlockSystem tube = tubeSystem(6, 12, 10);
  BlockSystem withTerm = tube;
  withTerm.off.push_back({5, 70, SymBlock::from(0.5 * Eigen::Matrix3d::Identity())});
  SupernodalCholesky factors;
  ASSERT_TRUE(factors.factorize(withTerm));
  ASSERT_TRUE(factors.factorize(tube));
  EXPECT_EQ(factors.analyses(), 1);
  expectSolvesAsDense(factors, tube, 11);
  ASSERT_TRUE(factors.factorize(withTerm));
  EXPECT_EQ(factors.analyses(), 1);
  expectSolvesAsDense(factors, withTerm, 12);
  // a new term between the tube's two ends: fill the structure does not have
  BlockSystem farther = tube;
  farther.off.push_back({0, tube.size() - 1, SymBlock::from(0.5 * Eigen::Matrix3d::Identity())});
  ASSERT_TRUE(factors.factorize(farther));
  EXPECT_EQ(factors.analyses(), 2);
  expectSolvesAsDense(factors, farther, 13);
}

TEST(SupernodalCholesky, RefusesAnIndefiniteMatrix) {
  BlockSystem a = randomSystem(30, 4, 5);
  a.diag[17](1, 1) = -1e3;
  SupernodalCholesky factors;
  EXPECT_FALSE(factors.factorize(a));
  // and factorises again once it is definite
  a.diag[17](1, 1) = 1e3;
  EXPECT_TRUE(factors.factorize(a));
  expectSolvesAsDense(factors, a, 8);
  // a tube's, wide supernodes and all, with one link far stiffer than the diagonal holds:
  // positive pivots until the later of its two nodes
  BlockSystem tube = tubeSystem(4, 8, 9);
  tube.off[20].m = SymBlock::from(1e3 * Eigen::Matrix3d::Identity());
  EXPECT_FALSE(factors.factorize(tube));
}

TEST(SupernodalCholesky, SolvesAnEmptySystem) {
  BlockSystem a;
  a.clear(0);
  SupernodalCholesky factors;
  ASSERT_TRUE(factors.factorize(a));
  Eigen::VectorXd x;
  factors.solve(Eigen::VectorXd(0), x);
  EXPECT_EQ(x.size(), 0);
}

}  // namespace
}  // namespace microsim::sim::detail
