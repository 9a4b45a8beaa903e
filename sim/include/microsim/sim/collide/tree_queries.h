#pragma once
// Queries on collision trees (sphere_tree.h): the paper's COLLISION and its all-pairs form,
// tree against tree or against itself, and points near a tree.
//
// COLLISION(N1, N2) (Brown et al. 2002 §5): if the volumes do not overlap, nothing below them
// can collide; if both are leaves, run the exact test of the two features; else open the
// larger volume (the one with the larger radius, or half-side for boxes; a leaf is never
// opened) and test its two children against the other. Here the recursion is an explicit
// stack. firstHit stops at the first colliding pair; allPairs reports every one.
//
// Exact tests by feature kinds: triangle–triangle (triangle_triangle.h), segment–triangle
// (segment_triangle.h), segment–segment (segment_segment.h). With margin = 0 two features
// collide when they intersect (closed sets: touching counts). With margin > 0 they collide
// when their distance is ≤ margin (mm), e.g. twice the suture radius for suture contact;
// every volume is then grown by margin/2.
//
// selfPairs walks a tree against itself: (N, N) opens into (L, L), (R, R), (L, R), and leaf
// pairs whose features share a vertex are skipped (neighbours in a mesh or chain always touch).
//
// Results are in traversal order, which is deterministic for a given tree and positions.
//
// Units: millimetres. Positions are 3 by #V.

#include "microsim/sim/collide/sphere_tree.h"

#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <vector>

namespace microsim::sim::collide {

/// A colliding pair: feature `first` of the first tree, `second` of the second (or of the
/// same tree, first < second, for selfPairs).
struct FeaturePair {
  int first = -1;
  int second = -1;
  friend bool operator==(const FeaturePair&, const FeaturePair&) = default;
};

/// Work a query did: volume overlap tests and exact feature tests.
struct QueryStats {
  std::int64_t volumeTests = 0;
  std::int64_t exactTests = 0;
};

/// A feature within reach of a query point.
struct PointNearFeature {
  int point = -1;              ///< column of the query points
  int feature = -1;            ///< the feature of the tree
  double distance = 0.0;       ///< mm
  Eigen::Vector3d closest;     ///< closest point on the feature, mm
  Eigen::Vector3d barycentric; ///< weights of the feature's vertices (third is 0 for segments)
};

/// The paper's COLLISION: the first colliding pair found, if any.
template <class Volume>
std::optional<FeaturePair> firstHit(const BvhTree<Volume>& a, const Points& xa,
                                    const BvhTree<Volume>& b, const Points& xb,
                                    double margin = 0.0, QueryStats* stats = nullptr);

/// Every colliding pair (feature of a, feature of b); `out` is cleared first.
template <class Volume>
void allPairs(const BvhTree<Volume>& a, const Points& xa, const BvhTree<Volume>& b,
              const Points& xb, std::vector<FeaturePair>& out, double margin = 0.0,
              QueryStats* stats = nullptr);

/// Every colliding pair of non-adjacent features of one tree, first < second; `out` is
/// cleared first.
template <class Volume>
void selfPairs(const BvhTree<Volume>& tree, const Points& x, std::vector<FeaturePair>& out,
               double margin = 0.0, QueryStats* stats = nullptr);

/// For each query point (3 by #P), every feature within `radius` (mm); `out` is cleared first.
template <class Volume>
void pointsNear(const BvhTree<Volume>& tree, const Points& x, const Points& points, double radius,
                std::vector<PointNearFeature>& out, QueryStats* stats = nullptr);

/// The exact test the queries use for one pair of features (kinds from the trees).
template <class Volume>
bool featuresCollide(const BvhTree<Volume>& a, const Points& xa, int fa, const BvhTree<Volume>& b,
                     const Points& xb, int fb, double margin = 0.0);

}  // namespace microsim::sim::collide
