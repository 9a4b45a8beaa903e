#include "microsim/sim/collide/tree_queries.h"

#include "bench/collision_shapes.h"
#include "microsim/sim/collide/point_triangle.h"
#include "microsim/sim/collide/segment_segment.h"
#include "microsim/sim/collide/segment_triangle.h"
#include "microsim/sim/collide/triangle_triangle.h"
#include "microsim/sim/mesh/grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>
#include <random>

namespace microsim::sim::collide {
namespace {

using microsim::bench::TriangleSoup;

std::vector<FeaturePair> sorted(std::vector<FeaturePair> pairs) {
  std::sort(pairs.begin(), pairs.end(), [](const FeaturePair& p, const FeaturePair& q) {
    return p.first < q.first || (p.first == q.first && p.second < q.second);
  });
  return pairs;
}

// every pair of features, in index order
template <class V>
std::vector<FeaturePair> bruteAllPairs(const BvhTree<V>& a, const Points& xa, const BvhTree<V>& b,
                                       const Points& xb, double margin) {
  std::vector<FeaturePair> out;
  for (int f = 0; f < a.featureCount(); ++f)
    for (int g = 0; g < b.featureCount(); ++g)
      if (featuresCollide(a, xa, f, b, xb, g, margin)) out.push_back({f, g});
  return out;
}

template <class V>
std::vector<FeaturePair> bruteSelfPairs(const BvhTree<V>& t, const Points& x, double margin) {
  std::vector<FeaturePair> out;
  for (int f = 0; f < t.featureCount(); ++f)
    for (int g = f + 1; g < t.featureCount(); ++g)
      if (!t.adjacent(f, g) && featuresCollide(t, x, f, t, x, g, margin)) out.push_back({f, g});
  return out;
}

template <class V>
class QueryTest : public ::testing::Test {};
using Volumes = ::testing::Types<Sphere, Aabb>;
TYPED_TEST_SUITE(QueryTest, Volumes);

TYPED_TEST(QueryTest, AllPairsEqualsBruteForceBeforeAndAfterDeformation) {
  // a 2 by 2 plane of 8 by 8 squares against a ball of radius 0.6 moving through it
  const SpringModel grid = gridMesh(8, 8, 0.25);
  Points plane = grid.restPositions();
  auto planeTree = BvhTree<TypeParam>::overTriangles(grid.triangles(), plane);
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> vertex(0, static_cast<int>(plane.cols()) - 1);
  std::uniform_real_distribution<double> radius(0.2, 1.0);
  std::uniform_real_distribution<double> height(-0.3, 0.3);
  std::uniform_real_distribution<double> offset(-0.5, 0.5);

  int colliding = 0;
  std::vector<FeaturePair> pairs;
  for (int round = 0; round < 12; ++round) {
    const double z = 0.9 - 0.15 * round;
    TriangleSoup ball = microsim::bench::uvBall(12, 7, 0.6, Vec3(offset(rng), offset(rng), z));
    auto ballTree = BvhTree<TypeParam>::overTriangles(ball.triangles, ball.x);

    for (const double margin : {0.0, 0.05}) {
      const std::vector<FeaturePair> want = bruteAllPairs(ballTree, ball.x, planeTree, plane, margin);
      QueryStats stats;
      allPairs(ballTree, ball.x, planeTree, plane, pairs, margin, &stats);
      EXPECT_EQ(sorted(pairs), want) << "round " << round << " margin " << margin;
      EXPECT_LE(stats.exactTests, ballTree.featureCount() * planeTree.featureCount());

      // the first hit is one of them, and exists iff they do
      const std::optional<FeaturePair> first = firstHit(ballTree, ball.x, planeTree, plane, margin);
      EXPECT_EQ(first.has_value(), !want.empty());
      if (first) {
        EXPECT_NE(std::find(want.begin(), want.end(), *first), want.end());
      }
      colliding += !want.empty();
    }

    // deform the plane and maintain its tree
    const std::vector<int> moved = microsim::bench::bump(plane, vertex(rng), radius(rng), height(rng));
    planeTree.maintainVertices(moved, plane);
  }
  EXPECT_GT(colliding, 6);
  EXPECT_LT(colliding, 24);
}

TYPED_TEST(QueryTest, SutureThroughTissue) {
  // a wavy chain crossing a plane several times: segment–triangle pairs
  const SpringModel grid = gridMesh(10, 10, 0.2);
  const Points& plane = grid.restPositions();
  auto planeTree = BvhTree<TypeParam>::overTriangles(grid.triangles(), plane);
  Points chain(3, 61);
  std::vector<std::array<int, 2>> links;
  links.reserve(60);
  for (int i = 0; i < 61; ++i)
    chain.col(i) = Vec3(-1.2 + 0.04 * i, 0.3 * std::sin(0.2 * i), 0.3 * std::sin(0.35 * i));
  for (int i = 0; i < 60; ++i) links.push_back({i, i + 1});
  auto chainTree = BvhTree<TypeParam>::overSegments(links, chain);

  std::vector<FeaturePair> pairs;
  const std::vector<FeaturePair> want = bruteAllPairs(chainTree, chain, planeTree, plane, 0.0);
  allPairs(chainTree, chain, planeTree, plane, pairs);
  EXPECT_FALSE(want.empty());
  EXPECT_EQ(sorted(pairs), want);

  // and the other way round
  const std::vector<FeaturePair> back = bruteAllPairs(planeTree, plane, chainTree, chain, 0.0);
  allPairs(planeTree, plane, chainTree, chain, pairs);
  EXPECT_EQ(sorted(pairs), back);
  EXPECT_EQ(back.size(), want.size());
}

// a chain of `count` links along the curve
template <class Curve>
std::pair<Points, std::vector<std::array<int, 2>>> chainAlong(int count, Curve curve) {
  Points x(3, count + 1);
  std::vector<std::array<int, 2>> links;
  links.reserve(static_cast<std::size_t>(count));
  for (int i = 0; i <= count; ++i) x.col(i) = curve(static_cast<double>(i) / count);
  for (int i = 0; i < count; ++i) links.push_back({i, i + 1});
  return {x, links};
}

TYPED_TEST(QueryTest, SelfCollisionOfAChain) {
  const double margin = 0.01;
  std::vector<FeaturePair> pairs;

  // straight: nothing
  const auto [straight, straightLinks] =
      chainAlong(100, [](double u) { return Vec3(6.0 * u, 0.0, 0.0); });
  auto straightTree = BvhTree<TypeParam>::overSegments(straightLinks, straight);
  selfPairs(straightTree, straight, pairs, margin);
  EXPECT_TRUE(pairs.empty());

  // most of a figure of eight rising slowly: one crossing, about 0.005 apart in z
  const auto [eight, eightLinks] = chainAlong(101, [](double u) {
    const double a = 2.0 * std::numbers::pi * (0.05 + 0.9 * u);
    return Vec3(std::cos(a), std::sin(a) * std::cos(a), 0.01 * u);
  });
  auto eightTree = BvhTree<TypeParam>::overSegments(eightLinks, eight);
  selfPairs(eightTree, eight, pairs, margin);
  const std::vector<FeaturePair> eightWant = bruteSelfPairs(eightTree, eight, margin);
  EXPECT_FALSE(eightWant.empty());
  EXPECT_EQ(sorted(pairs), eightWant);
  for (const FeaturePair& p : pairs) {
    // the two passes through the origin
    for (const int link : {p.first, p.second})
      EXPECT_LT(std::hypot(eight(0, link), eight(1, link)), 0.1);
  }

  // a hairpin: the chain folds back over itself 0.005 above
  const auto [fold, foldLinks] = chainAlong(80, [](double u) {
    return u < 0.5 ? Vec3(4.0 * u, 0.0, 0.0) : Vec3(4.0 * (1.0 - u), 0.0, 0.005);
  });
  auto foldTree = BvhTree<TypeParam>::overSegments(foldLinks, fold);
  selfPairs(foldTree, fold, pairs, margin);
  const std::vector<FeaturePair> foldWant = bruteSelfPairs(foldTree, fold, margin);
  EXPECT_GT(foldWant.size(), 60u);
  EXPECT_EQ(sorted(pairs), foldWant);
}

TYPED_TEST(QueryTest, SelfCollisionOfAFoldedSheet) {
  // a grid folded along x = 1 so the right half passes back through the left half
  const SpringModel grid = gridMesh(12, 4, 0.2);
  Points x = grid.restPositions();
  for (int v = 0; v < x.cols(); ++v) {
    const double over = x(0, v) - 0.3;
    if (over > 0.0) x.col(v) = Vec3(0.3 - over, x(1, v), 0.05 - 0.3 * over);
  }
  auto tree = BvhTree<TypeParam>::overTriangles(grid.triangles(), x);
  std::vector<FeaturePair> pairs;
  selfPairs(tree, x, pairs);
  const std::vector<FeaturePair> want = bruteSelfPairs(tree, x, 0.0);
  EXPECT_FALSE(want.empty());
  EXPECT_EQ(sorted(pairs), want);

  // flat: no pairs
  const Points& flat = grid.restPositions();
  auto flatTree = BvhTree<TypeParam>::overTriangles(grid.triangles(), flat);
  selfPairs(flatTree, flat, pairs);
  EXPECT_TRUE(pairs.empty());
}

TYPED_TEST(QueryTest, PointsNearEqualsBruteForce) {
  const SpringModel grid = gridMesh(10, 10, 0.3);
  Points x = grid.restPositions();
  microsim::bench::bump(x, 60, 1.0, 0.4);
  auto tree = BvhTree<TypeParam>::overTriangles(grid.triangles(), x);
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> coord(-2.0, 2.0);
  Points points(3, 60);
  for (int i = 0; i < 60; ++i) points.col(i) = Vec3(coord(rng), coord(rng), 0.25 * coord(rng));

  const double radius = 0.2;
  std::vector<PointNearFeature> near;
  pointsNear(tree, x, points, radius, near);
  std::vector<FeaturePair> got;
  for (const PointNearFeature& n : near) {
    got.push_back({n.point, n.feature});
    EXPECT_LE(n.distance, radius);
    EXPECT_NEAR((points.col(n.point) - n.closest).norm(), n.distance, 1e-12);
  }
  std::vector<FeaturePair> want;
  for (int i = 0; i < points.cols(); ++i)
    for (int f = 0; f < tree.featureCount(); ++f) {
      const auto v = tree.featureVertices(f);
      if (closestPointTriangle(points.col(i), x.col(v[0]), x.col(v[1]), x.col(v[2])).distance <= radius)
        want.push_back({i, f});
    }
  EXPECT_FALSE(want.empty());
  EXPECT_EQ(sorted(got), want);
}

}  // namespace
}  // namespace microsim::sim::collide
