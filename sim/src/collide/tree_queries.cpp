#include "microsim/sim/collide/tree_queries.h"

#include "microsim/sim/collide/point_triangle.h"
#include "microsim/sim/collide/segment_segment.h"
#include "microsim/sim/collide/segment_triangle.h"
#include "microsim/sim/collide/triangle_triangle.h"

#include <utility>

namespace microsim::sim::collide {

namespace {

struct NodePair {
  int a, b;
};

// COLLISION over node pairs with an explicit stack; onHit(fa, fb) returns true to stop.
// Returns true when stopped early.
template <class Volume, class OnHit>
bool descend(const BvhTree<Volume>& ta, const Points& xa, const BvhTree<Volume>& tb,
             const Points& xb, bool self, double margin, QueryStats& stats, OnHit&& onHit) {
  if (ta.empty() || tb.empty()) return false;
  std::vector<NodePair> stack;
  stack.reserve(3 * static_cast<std::size_t>(ta.height() + tb.height()) + 8);
  stack.push_back({0, 0});
  while (!stack.empty()) {
    const NodePair pair = stack.back();
    stack.pop_back();
    const auto& na = ta.node(pair.a);
    const auto& nb = tb.node(pair.b);

    // a subtree against itself: its two halves against themselves and each other
    if (self && pair.a == pair.b) {
      if (na.leaf()) continue;
      stack.push_back({na.left, na.right});
      stack.push_back({na.right, na.right});
      stack.push_back({na.left, na.left});
      continue;
    }

    // disjoint volumes: nothing below collides
    ++stats.volumeTests;
    if (!overlaps(ta.volume(pair.a), tb.volume(pair.b), margin)) continue;

    // two leaves: the exact test
    if (na.leaf() && nb.leaf()) {
      if (self && ta.adjacent(na.feature, nb.feature)) continue;
      ++stats.exactTests;
      if (!featuresCollide(ta, xa, na.feature, tb, xb, nb.feature, margin)) continue;
      if (onHit(na.feature, nb.feature)) return true;
      continue;
    }

    // open the larger volume
    const bool openA =
        !na.leaf() && (nb.leaf() || volumeSize(ta.volume(pair.a)) >= volumeSize(tb.volume(pair.b)));
    if (openA) {
      stack.push_back({na.right, pair.b});
      stack.push_back({na.left, pair.b});
    } else {
      stack.push_back({pair.a, nb.right});
      stack.push_back({pair.a, nb.left});
    }
  }
  return false;
}

}  // namespace

template <class Volume>
bool featuresCollide(const BvhTree<Volume>& a, const Points& xa, int fa, const BvhTree<Volume>& b,
                     const Points& xb, int fb, double margin) {
  const std::span<const int> va = a.featureVertices(fa);
  const std::span<const int> vb = b.featureVertices(fb);
  const bool triA = a.kind() == FeatureKind::Triangle;
  const bool triB = b.kind() == FeatureKind::Triangle;

  // triangle against triangle
  if (triA && triB) {
    if (margin <= 0.0)
      return trianglesIntersect(xa.col(va[0]), xa.col(va[1]), xa.col(va[2]), xb.col(vb[0]),
                                xb.col(vb[1]), xb.col(vb[2]));
    return triangleTriangleDistance(xa.col(va[0]), xa.col(va[1]), xa.col(va[2]), xb.col(vb[0]),
                                    xb.col(vb[1]), xb.col(vb[2])) <= margin;
  }

  // segment against segment
  if (!triA && !triB)
    return closestSegmentSegment(xa.col(va[0]), xa.col(va[1]), xb.col(vb[0]), xb.col(vb[1]))
               .distance <= margin;

  // segment against triangle, either way round
  const Points& xs = triA ? xb : xa;
  const Points& xt = triA ? xa : xb;
  const std::span<const int> s = triA ? vb : va;
  const std::span<const int> t = triA ? va : vb;
  if (margin <= 0.0)
    return intersectSegmentTriangle(xs.col(s[0]), xs.col(s[1]), xt.col(t[0]), xt.col(t[1]),
                                    xt.col(t[2]))
        .has_value();
  return segmentTriangleDistance(xs.col(s[0]), xs.col(s[1]), xt.col(t[0]), xt.col(t[1]),
                                 xt.col(t[2])) <= margin;
}

template <class Volume>
std::optional<FeaturePair> firstHit(const BvhTree<Volume>& a, const Points& xa,
                                    const BvhTree<Volume>& b, const Points& xb, double margin,
                                    QueryStats* stats) {
  QueryStats local;
  std::optional<FeaturePair> hit;
  descend(a, xa, b, xb, false, margin, stats ? *stats : local, [&](int fa, int fb) {
    hit = FeaturePair{fa, fb};
    return true;
  });
  return hit;
}

template <class Volume>
void allPairs(const BvhTree<Volume>& a, const Points& xa, const BvhTree<Volume>& b,
              const Points& xb, std::vector<FeaturePair>& out, double margin, QueryStats* stats) {
  QueryStats local;
  out.clear();
  descend(a, xa, b, xb, false, margin, stats ? *stats : local, [&](int fa, int fb) {
    out.push_back({fa, fb});
    return false;
  });
}

template <class Volume>
void selfPairs(const BvhTree<Volume>& tree, const Points& x, std::vector<FeaturePair>& out,
               double margin, QueryStats* stats) {
  QueryStats local;
  out.clear();
  descend(tree, x, tree, x, true, margin, stats ? *stats : local, [&](int fa, int fb) {
    out.push_back({std::min(fa, fb), std::max(fa, fb)});
    return false;
  });
}

template <class Volume>
void pointsNear(const BvhTree<Volume>& tree, const Points& x, const Points& points, double radius,
                std::vector<PointNearFeature>& out, QueryStats* stats) {
  QueryStats local;
  QueryStats& st = stats ? *stats : local;
  out.clear();
  if (tree.empty()) return;
  std::vector<int> stack;
  stack.reserve(static_cast<std::size_t>(tree.height()) + 2);
  for (int i = 0; i < points.cols(); ++i) {
    const Vec3 p = points.col(i);
    stack.clear();
    stack.push_back(0);
    while (!stack.empty()) {
      const int n = stack.back();
      stack.pop_back();
      ++st.volumeTests;
      if (!near(tree.volume(n), p, radius)) continue;
      const auto& node = tree.node(n);
      if (!node.leaf()) {
        stack.push_back(node.right);
        stack.push_back(node.left);
        continue;
      }

      // the exact distance to the leaf's feature
      ++st.exactTests;
      const std::span<const int> v = tree.featureVertices(node.feature);
      PointNearFeature hit;
      hit.point = i;
      hit.feature = node.feature;
      if (tree.kind() == FeatureKind::Triangle) {
        const PointTriangleClosest c = closestPointTriangle(p, x.col(v[0]), x.col(v[1]), x.col(v[2]));
        hit.distance = c.distance;
        hit.closest = c.point;
        hit.barycentric = c.barycentric;
      } else {
        const double t = closestParameterOnSegment(p, x.col(v[0]), x.col(v[1]));
        hit.closest = (1.0 - t) * x.col(v[0]) + t * x.col(v[1]);
        hit.distance = (p - hit.closest).norm();
        hit.barycentric = Vec3(1.0 - t, t, 0.0);
      }
      if (hit.distance <= radius) out.push_back(hit);
    }
  }
}

#define MICROSIM_COLLIDE_INSTANTIATE(V)                                                       \
  template bool featuresCollide<V>(const BvhTree<V>&, const Points&, int, const BvhTree<V>&, \
                                   const Points&, int, double);                              \
  template std::optional<FeaturePair> firstHit<V>(const BvhTree<V>&, const Points&,          \
                                                  const BvhTree<V>&, const Points&, double,  \
                                                  QueryStats*);                              \
  template void allPairs<V>(const BvhTree<V>&, const Points&, const BvhTree<V>&,             \
                            const Points&, std::vector<FeaturePair>&, double, QueryStats*);  \
  template void selfPairs<V>(const BvhTree<V>&, const Points&, std::vector<FeaturePair>&,    \
                             double, QueryStats*);                                           \
  template void pointsNear<V>(const BvhTree<V>&, const Points&, const Points&, double,        \
                              std::vector<PointNearFeature>&, QueryStats*);

MICROSIM_COLLIDE_INSTANTIATE(Sphere)
MICROSIM_COLLIDE_INSTANTIATE(Aabb)

#undef MICROSIM_COLLIDE_INSTANTIATE

}  // namespace microsim::sim::collide
