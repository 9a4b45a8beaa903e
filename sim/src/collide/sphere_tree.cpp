#include "microsim/sim/collide/sphere_tree.h"

#include <algorithm>
#include <cassert>

namespace microsim::sim::collide {

template <class Volume>
BvhTree<Volume> BvhTree<Volume>::overTriangles(std::span<const std::array<int, 3>> triangles,
                                               const Points& x) {
  BvhTree tree;
  tree.kind_ = FeatureKind::Triangle;
  tree.arity_ = 3;
  tree.featureVertices_.reserve(triangles.size() * 3);
  for (const auto& t : triangles) tree.featureVertices_.insert(tree.featureVertices_.end(), t.begin(), t.end());
  tree.build(x, static_cast<int>(x.cols()));
  return tree;
}

template <class Volume>
BvhTree<Volume> BvhTree<Volume>::overSegments(std::span<const std::array<int, 2>> segments,
                                              const Points& x) {
  BvhTree tree;
  tree.kind_ = FeatureKind::Segment;
  tree.arity_ = 2;
  tree.featureVertices_.reserve(segments.size() * 2);
  for (const auto& s : segments) tree.featureVertices_.insert(tree.featureVertices_.end(), s.begin(), s.end());
  tree.build(x, static_cast<int>(x.cols()));
  return tree;
}

template <class Volume>
void BvhTree<Volume>::refitNode(int n, const Points& x) {
  const Node& node = nodes_[n];
  if (node.leaf()) {
    const int* v = featureVertices_.data() + static_cast<std::size_t>(node.feature) * arity_;
    volumes_[n] = arity_ == 3 ? VolumeTraits<Volume>::fit(x.col(v[0]), x.col(v[1]), x.col(v[2]))
                              : VolumeTraits<Volume>::fit(x.col(v[0]), x.col(v[1]));
  } else {
    volumes_[n] = VolumeTraits<Volume>::merge(volumes_[node.left], volumes_[node.right]);
  }
}

template <class Volume>
void BvhTree<Volume>::build(const Points& x, int vertexCount) {
  const int features = static_cast<int>(featureVertices_.size()) / arity_;
  leafOf_.assign(features, -1);
  nodes_.clear();
  volumes_.clear();
  levels_.clear();
  if (features == 0) return;
  nodes_.reserve(2 * static_cast<std::size_t>(features) - 1);
  volumes_.resize(2 * static_cast<std::size_t>(features) - 1);

  // leaf volumes and their centres, indexed by feature
  std::vector<Volume> leafVolumes(features);
  std::vector<Vec3> centres(features);
  for (int f = 0; f < features; ++f) {
    const int* v = featureVertices_.data() + static_cast<std::size_t>(f) * arity_;
    leafVolumes[f] = arity_ == 3 ? VolumeTraits<Volume>::fit(x.col(v[0]), x.col(v[1]), x.col(v[2]))
                                 : VolumeTraits<Volume>::fit(x.col(v[0]), x.col(v[1]));
    centres[f] = volumeCentre(leafVolumes[f]);
  }

  // top-down median split with an explicit stack of (node, begin, end) over `order`
  std::vector<int> order(features);
  for (int f = 0; f < features; ++f) order[f] = f;
  struct Range {
    int node, begin, end;
  };
  std::vector<Range> stack;
  nodes_.push_back(Node{});
  stack.push_back({0, 0, features});
  int height = 0;
  while (!stack.empty()) {
    const Range r = stack.back();
    stack.pop_back();
    height = std::max(height, nodes_[r.node].depth);
    if (r.end - r.begin == 1) {
      const int f = order[r.begin];
      nodes_[r.node].feature = f;
      leafOf_[f] = r.node;
      volumes_[r.node] = leafVolumes[f];
      continue;
    }

    // the longest side of the box of centres
    Vec3 lo = centres[order[r.begin]];
    Vec3 hi = lo;
    for (int i = r.begin + 1; i < r.end; ++i) {
      lo = lo.cwiseMin(centres[order[i]]);
      hi = hi.cwiseMax(centres[order[i]]);
    }
    int axis = 0;
    (hi - lo).maxCoeff(&axis);

    // equal halves; ties broken by feature index so the tree is unique
    const int mid = r.begin + (r.end - r.begin) / 2;
    std::nth_element(order.begin() + r.begin, order.begin() + mid, order.begin() + r.end,
                     [&](int f, int g) {
                       const double cf = centres[f][axis];
                       const double cg = centres[g][axis];
                       return cf < cg || (cf == cg && f < g);
                     });

    // the two children, allocated together after their parent
    const int left = static_cast<int>(nodes_.size());
    const int depth = nodes_[r.node].depth + 1;
    nodes_.push_back(Node{-1, -1, r.node, -1, depth});
    nodes_.push_back(Node{-1, -1, r.node, -1, depth});
    nodes_[r.node].left = left;
    nodes_[r.node].right = left + 1;
    stack.push_back({left + 1, mid, r.end});
    stack.push_back({left, r.begin, mid});
  }

  // internal volumes, children first
  for (int n = static_cast<int>(nodes_.size()) - 1; n >= 0; --n)
    if (!nodes_[n].leaf()) refitNode(n, x);

  // vertex → features
  vertexFeatureStart_.assign(static_cast<std::size_t>(vertexCount) + 1, 0);
  for (int v : featureVertices_) ++vertexFeatureStart_[v + 1];
  for (int v = 0; v < vertexCount; ++v) vertexFeatureStart_[v + 1] += vertexFeatureStart_[v];
  vertexFeatures_.assign(featureVertices_.size(), 0);
  std::vector<int> fill(vertexFeatureStart_.begin(), vertexFeatureStart_.end() - 1);
  for (int f = 0; f < features; ++f)
    for (int k = 0; k < arity_; ++k) vertexFeatures_[fill[featureVertices_[f * arity_ + k]]++] = f;

  // maintenance scratch sized once: a bucket per depth
  levels_.assign(static_cast<std::size_t>(height) + 1, {});
  std::vector<int> perDepth(static_cast<std::size_t>(height) + 1, 0);
  for (const Node& node : nodes_) ++perDepth[node.depth];
  for (int d = 0; d <= height; ++d) levels_[d].reserve(perDepth[d]);
  stamp_.assign(nodes_.size(), 0);
  generation_ = 0;
}

template <class Volume>
int BvhTree<Volume>::refitAll(const Points& x) {
  for (int n = static_cast<int>(nodes_.size()) - 1; n >= 0; --n) refitNode(n, x);
  return nodeCount();
}

template <class Volume>
int BvhTree<Volume>::maintain(std::span<const int> deformedFeatures, const Points& x) {
  if (nodes_.empty()) return 0;
  if (++generation_ == 0) {
    std::fill(stamp_.begin(), stamp_.end(), 0u);
    generation_ = 1;
  }

  // the deformed leaves, each once, into the bucket of its depth
  int deepest = -1;
  for (const int f : deformedFeatures) {
    const int n = leafOf_[f];
    if (stamp_[n] == generation_) continue;
    stamp_[n] = generation_;
    const int d = nodes_[n].depth;
    levels_[d].push_back(n);
    deepest = std::max(deepest, d);
  }

  // deepest first: refit, then queue the parent once
  int refits = 0;
  for (int d = deepest; d >= 0; --d) {
    std::vector<int>& level = levels_[d];
    for (const int n : level) {
      refitNode(n, x);
      ++refits;
      const int p = nodes_[n].parent;
      if (p >= 0 && stamp_[p] != generation_) {
        stamp_[p] = generation_;
        levels_[d - 1].push_back(p);
      }
    }
    level.clear();
  }
  return refits;
}

template <class Volume>
int BvhTree<Volume>::maintainVertices(std::span<const int> movedVertices, const Points& x) {
  scratch_.clear();
  for (const int v : movedVertices)
    for (int k = vertexFeatureStart_[v]; k < vertexFeatureStart_[v + 1]; ++k)
      scratch_.push_back(vertexFeatures_[k]);
  return maintain(scratch_, x);
}

template <class Volume>
bool BvhTree<Volume>::adjacent(int f, int g) const {
  const std::span<const int> a = featureVertices(f);
  const std::span<const int> b = featureVertices(g);
  for (const int u : a)
    for (const int v : b)
      if (u == v) return true;
  return false;
}

template class BvhTree<Sphere>;
template class BvhTree<Aabb>;

}  // namespace microsim::sim::collide
