#pragma once
// Bounding volumes of the collision trees: the paper's spheres (Brown et al. 2002 §5, after
// Quinlan 1994) and axis-aligned boxes. Both are pure value types with free fitting and
// merging kernels; a tree is generic over the volume (see sphere_tree.h).
//
// Leaf fit of a triangle (a, b, c): the smallest enclosing sphere is the circumsphere when
// the triangle is acute or right (every angle ≤ 90°), else the sphere whose diameter is the
// longest edge. Zero-area triangles fall in the second case. Leaf fit of a segment (a, b):
// centre (a + b)/2, radius |b − a|/2.
//
// Merge of two spheres (c1, r1), (c2, r2), d = |c2 − c1|: if d + r2 ≤ r1 the first encloses
// the second (and symmetrically); else r = (d + r1 + r2)/2 and c = c1 + (r − r1)(c2 − c1)/d,
// the smallest sphere enclosing both spheres (not their contents, the paper's rule).
//
// Every leaf fit is inflated by 2e-12 of the coordinates' scale, twice the exact tests'
// tolerance, so that rounding never lets a volume reject a pair the exact test accepts
// (queries must have no false negatives).
//
// Units: millimetres.

#include <Eigen/Core>

#include <algorithm>

namespace microsim::sim::collide {

using Vec3 = Eigen::Vector3d;

struct Sphere {
  Vec3 centre = Vec3::Zero();  ///< mm
  double radius = 0.0;         ///< mm, ≥ 0
};

struct Aabb {
  Vec3 lo = Vec3::Zero();  ///< minimum corner, mm
  Vec3 hi = Vec3::Zero();  ///< maximum corner, mm
};

/// Smallest sphere enclosing the triangle (a, b, c).
Sphere fitSphere(const Vec3& a, const Vec3& b, const Vec3& c);
/// Smallest sphere enclosing the segment (a, b).
Sphere fitSphere(const Vec3& a, const Vec3& b);
/// Smallest sphere enclosing the spheres s and t.
Sphere mergeSpheres(const Sphere& s, const Sphere& t);

/// True when the spheres, each grown by margin/2 (mm), intersect or touch.
inline bool overlaps(const Sphere& s, const Sphere& t, double margin = 0.0) {
  const double reach = s.radius + t.radius + margin;
  return (s.centre - t.centre).squaredNorm() <= reach * reach;
}
/// True when the point lies within `radius` (mm) of the sphere.
inline bool near(const Sphere& s, const Vec3& p, double radius) {
  const double reach = s.radius + radius;
  return (s.centre - p).squaredNorm() <= reach * reach;
}
/// The size a traversal compares to decide which volume to open: the radius.
inline double volumeSize(const Sphere& s) { return s.radius; }
inline Vec3 volumeCentre(const Sphere& s) { return s.centre; }

/// Box of the triangle (a, b, c).
Aabb fitAabb(const Vec3& a, const Vec3& b, const Vec3& c);
/// Box of the segment (a, b).
Aabb fitAabb(const Vec3& a, const Vec3& b);
inline Aabb mergeAabbs(const Aabb& s, const Aabb& t) {
  return {s.lo.cwiseMin(t.lo), s.hi.cwiseMax(t.hi)};
}

/// True when the boxes, each grown by margin/2 (mm) on every side, intersect or touch.
inline bool overlaps(const Aabb& s, const Aabb& t, double margin = 0.0) {
  return s.lo.x() <= t.hi.x() + margin && t.lo.x() <= s.hi.x() + margin &&
         s.lo.y() <= t.hi.y() + margin && t.lo.y() <= s.hi.y() + margin &&
         s.lo.z() <= t.hi.z() + margin && t.lo.z() <= s.hi.z() + margin;
}
/// True when the point lies within `radius` (mm) of the box (Euclidean distance).
inline bool near(const Aabb& s, const Vec3& p, double radius) {
  const Vec3 outside = (s.lo - p).cwiseMax(p - s.hi).cwiseMax(0.0);
  return outside.squaredNorm() <= radius * radius;
}
/// Half the longest side: the box's counterpart of a radius.
inline double volumeSize(const Aabb& s) { return 0.5 * (s.hi - s.lo).maxCoeff(); }
inline Vec3 volumeCentre(const Aabb& s) { return 0.5 * (s.lo + s.hi); }

/// The fitting rules a tree needs from its volume type, in one place.
template <class Volume>
struct VolumeTraits;

template <>
struct VolumeTraits<Sphere> {
  static Sphere fit(const Vec3& a, const Vec3& b, const Vec3& c) { return fitSphere(a, b, c); }
  static Sphere fit(const Vec3& a, const Vec3& b) { return fitSphere(a, b); }
  static Sphere merge(const Sphere& s, const Sphere& t) { return mergeSpheres(s, t); }
};

template <>
struct VolumeTraits<Aabb> {
  static Aabb fit(const Vec3& a, const Vec3& b, const Vec3& c) { return fitAabb(a, b, c); }
  static Aabb fit(const Vec3& a, const Vec3& b) { return fitAabb(a, b); }
  static Aabb merge(const Aabb& s, const Aabb& t) { return mergeAabbs(s, t); }
};

}  // namespace microsim::sim::collide
