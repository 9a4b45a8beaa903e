#pragma once
// Deformable sphere trees (Brown et al. 2002 §5, after Quinlan 1994), and the same tree over
// axis-aligned boxes.
//
// What the tree is. One leaf per feature: a triangle of a tissue surface or a segment of a
// suture (one link). A leaf's volume is the feature's smallest enclosing sphere
// (bounding_volume.h). The tree is binary and approximately balanced: the leaves are split
// recursively into two halves of equal count (the lower gets ⌊n/2⌋) across the longest
// side of the axis-aligned box of their volume centres. Every internal volume encloses its
// two child volumes. The topology is fixed at build time and never changes afterwards: when
// the tissue deforms only the volumes move, which is what makes maintenance cheap.
//
// Layout. Nodes live in one flat array, root at index 0; the two children of a node are
// allocated together and always after their parent, so a reverse sweep over the array visits
// every child before its parent (the full refit). Leaves appear in build order, which keeps
// spatial neighbours close in memory. A node stores its children, its parent, its depth and
// (leaves only) its feature; the volumes sit in a parallel array. Nothing is allocated per
// node, and no query allocates per node either (queries use an explicit stack).
//
// MAINTENANCE (the paper's algorithm). Before a query, the caller names the features that
// deformed since the last maintenance. Their leaves enter a queue ordered by depth, deepest
// first (here: one bucket per depth, swept from the deepest bucket up). Popping node w refits
// w from its feature (a leaf) or from its two children (internal), then queues parent(w) if
// it is not queued yet. A generation stamp per node marks "queued in this maintenance", so
// each ancestor is refit exactly once, after all its queued descendants. Cost: O(k + log s)
// for k features of one local deformation, O(k log s) for scattered ones, O(s) worst case,
// with s leaves. maintain() returns how many volumes it refit = |deformed leaves ∪ their
// ancestors|, which the tests assert.
//
// Invariants (after build, refitAll, or a maintain() naming every feature whose vertices
// moved): each leaf volume encloses its feature at the given positions; each internal
// volume encloses its two children's volumes; node(0) is the root; node(i).parent < i.
//
// Units: millimetres. Positions are "3 by #V" (column i is vertex i).

#include "microsim/sim/collide/bounding_volume.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace microsim::sim::collide {

/// Vertex positions: 3 by #V, column i is vertex i (mm).
using Points = Eigen::Matrix3Xd;

enum class FeatureKind : std::uint8_t { Triangle, Segment };

template <class Volume>
class BvhTree {
 public:
  struct Node {
    int left = -1;     ///< first child, -1 for a leaf
    int right = -1;    ///< second child, -1 for a leaf
    int parent = -1;   ///< -1 for the root
    int feature = -1;  ///< the leaf's feature, -1 for internal nodes
    int depth = 0;     ///< root = 0
    bool leaf() const { return left < 0; }
  };

  BvhTree() = default;
  /// A tree over triangles (vertex indices into x's columns), fitted to x.
  static BvhTree overTriangles(std::span<const std::array<int, 3>> triangles, const Points& x);
  /// A tree over segments (e.g. the links of a suture), fitted to x.
  static BvhTree overSegments(std::span<const std::array<int, 2>> segments, const Points& x);

  /// The paper's MAINTENANCE: refits the leaves of the named features and each of their
  /// ancestors once. Duplicates are allowed. Returns the number of volumes refit.
  int maintain(std::span<const int> deformedFeatures, const Points& x);
  /// maintain() for every feature touching one of the moved vertices.
  int maintainVertices(std::span<const int> movedVertices, const Points& x);
  /// Refits every volume (leaves, then internal nodes children first). Returns nodeCount().
  int refitAll(const Points& x);

  FeatureKind kind() const { return kind_; }
  /// 3 for triangles, 2 for segments.
  int featureArity() const { return arity_; }
  int featureCount() const { return static_cast<int>(leafOf_.size()); }
  int nodeCount() const { return static_cast<int>(nodes_.size()); }
  /// Depth of the deepest leaf (0 for a single leaf).
  int height() const { return static_cast<int>(levels_.size()) - 1; }
  bool empty() const { return nodes_.empty(); }

  const Node& node(int i) const { return nodes_[i]; }
  const Volume& volume(int i) const { return volumes_[i]; }
  int leafOf(int feature) const { return leafOf_[feature]; }
  /// The feature's vertex indices (featureArity() of them).
  std::span<const int> featureVertices(int feature) const {
    return {featureVertices_.data() + static_cast<std::size_t>(feature) * arity_,
            static_cast<std::size_t>(arity_)};
  }
  /// True when the two features share a vertex (self-collision skips those pairs).
  bool adjacent(int f, int g) const;

 private:
  void build(const Points& x, int vertexCount);
  void refitNode(int n, const Points& x);

  FeatureKind kind_ = FeatureKind::Triangle;
  int arity_ = 3;
  std::vector<int> featureVertices_;  // featureCount × arity
  std::vector<Node> nodes_;
  std::vector<Volume> volumes_;
  std::vector<int> leafOf_;
  // vertex → features touching it, compressed rows
  std::vector<int> vertexFeatureStart_;
  std::vector<int> vertexFeatures_;
  // maintenance scratch: a bucket per depth and a queued-in-generation stamp per node
  std::vector<std::vector<int>> levels_;
  std::vector<std::uint32_t> stamp_;
  std::uint32_t generation_ = 0;
  std::vector<int> scratch_;  // features of moved vertices
};

/// The paper's reference tree.
using SphereTree = BvhTree<Sphere>;
/// The same tree over axis-aligned boxes (see the benchmark for which is faster).
using AabbTree = BvhTree<Aabb>;

extern template class BvhTree<Sphere>;
extern template class BvhTree<Aabb>;

}  // namespace microsim::sim::collide
