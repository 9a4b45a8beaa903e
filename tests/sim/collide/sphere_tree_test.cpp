#include "microsim/sim/collide/sphere_tree.h"

#include "bench/collision_shapes.h"
#include "microsim/sim/mesh/grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

namespace microsim::sim::collide {
namespace {

bool holds(const Sphere& s, const Vec3& p) { return (p - s.centre).norm() <= s.radius; }
bool holds(const Aabb& b, const Vec3& p) {
  return (p.array() >= b.lo.array()).all() && (p.array() <= b.hi.array()).all();
}
bool holds(const Sphere& outer, const Sphere& inner) {
  return (inner.centre - outer.centre).norm() + inner.radius <= outer.radius;
}
bool holds(const Aabb& outer, const Aabb& inner) {
  return (inner.lo.array() >= outer.lo.array()).all() && (inner.hi.array() <= outer.hi.array()).all();
}
bool same(const Sphere& s, const Sphere& t) { return s.centre == t.centre && s.radius == t.radius; }
bool same(const Aabb& s, const Aabb& t) { return s.lo == t.lo && s.hi == t.hi; }

template <class V>
void expectInvariants(const BvhTree<V>& tree, const Points& x) {
  const int features = tree.featureCount();
  ASSERT_EQ(tree.nodeCount(), 2 * features - 1);
  EXPECT_LE(tree.height(), static_cast<int>(std::ceil(std::log2(features))));
  EXPECT_EQ(tree.node(0).parent, -1);
  for (int n = 0; n < tree.nodeCount(); ++n) {
    const auto& node = tree.node(n);
    if (n > 0) {
      EXPECT_LT(node.parent, n);
      EXPECT_EQ(node.depth, tree.node(node.parent).depth + 1);
    }
    if (node.leaf()) {
      EXPECT_EQ(tree.leafOf(node.feature), n);
      for (const int v : tree.featureVertices(node.feature))
        EXPECT_TRUE(holds(tree.volume(n), Vec3(x.col(v)))) << "leaf " << n;
    } else {
      EXPECT_EQ(tree.node(node.left).parent, n);
      EXPECT_EQ(tree.node(node.right).parent, n);
      EXPECT_TRUE(holds(tree.volume(n), tree.volume(node.left))) << "node " << n;
      EXPECT_TRUE(holds(tree.volume(n), tree.volume(node.right))) << "node " << n;
    }
  }
}

// the deformed leaves and every one of their ancestors
template <class V>
std::set<int> leavesAndAncestors(const BvhTree<V>& tree, const std::vector<int>& features) {
  std::set<int> nodes;
  for (const int f : features)
    for (int n = tree.leafOf(f); n >= 0; n = tree.node(n).parent) nodes.insert(n);
  return nodes;
}

template <class V>
class TreeTest : public ::testing::Test {};
using Volumes = ::testing::Types<Sphere, Aabb>;
TYPED_TEST_SUITE(TreeTest, Volumes);

TYPED_TEST(TreeTest, BuildIsBalancedAndEnclosing) {
  const SpringModel grid = gridMesh(13, 11, 0.5);
  const Points& x = grid.restPositions();
  const auto tree = BvhTree<TypeParam>::overTriangles(grid.triangles(), x);
  EXPECT_EQ(tree.featureCount(), 2 * 13 * 11);
  EXPECT_EQ(tree.kind(), FeatureKind::Triangle);
  expectInvariants(tree, x);

  // leaf depths differ by at most one (equal halves)
  int shallowest = tree.height();
  for (int n = 0; n < tree.nodeCount(); ++n)
    if (tree.node(n).leaf()) shallowest = std::min(shallowest, tree.node(n).depth);
  EXPECT_GE(shallowest, tree.height() - 1);
}

TYPED_TEST(TreeTest, MaintenanceRefitsExactlyTheAncestorsOfDeformedLeaves) {
  const SpringModel grid = gridMesh(16, 16, 1.0);
  Points x = grid.restPositions();
  auto tree = BvhTree<TypeParam>::overTriangles(grid.triangles(), x);
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> vertex(0, static_cast<int>(x.cols()) - 1);
  std::uniform_real_distribution<double> radius(1.0, 4.0);
  std::uniform_real_distribution<double> height(-1.0, 1.0);

  for (int round = 0; round < 30; ++round) {
    // a local bump, or several scattered ones
    std::vector<int> moved;
    const int bumps = round % 2 == 0 ? 1 : 4;
    for (int b = 0; b < bumps; ++b) {
      const std::vector<int> m = microsim::bench::bump(x, vertex(rng), radius(rng), height(rng));
      moved.insert(moved.end(), m.begin(), m.end());
    }
    std::vector<int> features;
    for (int f = 0; f < tree.featureCount(); ++f)
      for (const int v : tree.featureVertices(f))
        if (std::find(moved.begin(), moved.end(), v) != moved.end()) {
          features.push_back(f);
          break;
        }

    // maintain: the count is the deformed leaves plus their ancestors, nothing else changes
    const std::set<int> expected = leavesAndAncestors(tree, features);
    std::vector<TypeParam> before;
    before.reserve(static_cast<std::size_t>(tree.nodeCount()));
    for (int n = 0; n < tree.nodeCount(); ++n) before.push_back(tree.volume(n));
    const int refits = round % 3 == 0 ? tree.maintainVertices(moved, x) : tree.maintain(features, x);
    EXPECT_EQ(refits, static_cast<int>(expected.size()));
    for (int n = 0; n < tree.nodeCount(); ++n)
      if (!expected.count(n)) {
        EXPECT_TRUE(same(before[n], tree.volume(n))) << "node " << n;
      }
    expectInvariants(tree, x);
  }
}

TYPED_TEST(TreeTest, MaintenanceCounts) {
  const SpringModel grid = gridMesh(8, 8, 1.0);
  Points x = grid.restPositions();
  auto tree = BvhTree<TypeParam>::overTriangles(grid.triangles(), x);
  EXPECT_EQ(tree.maintain({}, x), 0);
  // one leaf: itself and its ancestors up to the root
  const std::vector<int> one = {17};
  EXPECT_EQ(tree.maintain(one, x), tree.node(tree.leafOf(17)).depth + 1);
  // duplicates count once
  const std::vector<int> twice = {17, 17};
  EXPECT_EQ(tree.maintain(twice, x), tree.node(tree.leafOf(17)).depth + 1);
  // every leaf: every node
  std::vector<int> all(tree.featureCount());
  for (int f = 0; f < tree.featureCount(); ++f) all[f] = f;
  EXPECT_EQ(tree.maintain(all, x), tree.nodeCount());
  // a full refit after moving everything
  x.row(2).setConstant(3.0);
  EXPECT_EQ(tree.refitAll(x), tree.nodeCount());
  expectInvariants(tree, x);
}

TYPED_TEST(TreeTest, SegmentTreeOverAChain) {
  Points x(3, 41);
  std::vector<std::array<int, 2>> links;
  links.reserve(40);
  for (int i = 0; i < 41; ++i) x.col(i) = Vec3(std::cos(0.3 * i), std::sin(0.3 * i), 0.05 * i);
  for (int i = 0; i < 40; ++i) links.push_back({i, i + 1});
  auto tree = BvhTree<TypeParam>::overSegments(links, x);
  EXPECT_EQ(tree.kind(), FeatureKind::Segment);
  EXPECT_EQ(tree.featureArity(), 2);
  expectInvariants(tree, x);
  EXPECT_TRUE(tree.adjacent(3, 4));
  EXPECT_FALSE(tree.adjacent(3, 5));
  x.col(20) += Vec3(0.5, -0.2, 1.0);
  const std::vector<int> moved = {20};
  const std::vector<int> features = {19, 20};
  EXPECT_EQ(tree.maintainVertices(moved, x), static_cast<int>(leavesAndAncestors(tree, features).size()));
  expectInvariants(tree, x);
}

}  // namespace
}  // namespace microsim::sim::collide
