#pragma once
// Segment against triangle (piercing: a needle edge through a vessel face; cutting; draping).
//
// The segment p + t (q − p), t ∈ [0, 1], and the closed triangle (a, b, c). With the plane
// normal n = (b − a) × (c − a), the end points lie on opposite sides (or on the plane) when
// n·(p − a) and n·(q − a) do not share a strict sign. The line then crosses the triangle iff
// the three signed volumes U = [q−p, c−p, b−p], V = [q−p, a−p, c−p], W = [q−p, b−p, a−p]
// share a sign (zero allowed), and the hit is X = (U a + V b + W c)/(U + V + W) at
// t = n·(p − a) / n·(p − q) (Ericson §5.3.4, with a signed-volume inside test that is exact
// for small integer coordinates, so touching cases are decided exactly).
//
// Coplanar segments and zero-area triangles have no unique crossing: the hit is then the
// first point along the segment that lies in the triangle (t = 0 if p is inside, else the
// first crossing with an edge within a tolerance of 1e-12 of the coordinates' scale).
//
// Units: millimetres.

#include <Eigen/Core>

#include <optional>

namespace microsim::sim::collide {

struct SegmentTriangleHit {
  double t = 0.0;              ///< hit = p + t (q − p), t ∈ [0, 1]
  Eigen::Vector3d point;       ///< the hit point, mm
  Eigen::Vector3d barycentric; ///< (u, v, w): point = u a + v b + w c, each ≥ 0, sum 1
};

/// The first point of the segment (p, q) in the closed triangle (a, b, c), if any.
std::optional<SegmentTriangleHit> intersectSegmentTriangle(
    const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Eigen::Vector3d& a,
    const Eigen::Vector3d& b, const Eigen::Vector3d& c);

/// Smallest distance (mm) between the segment (p, q) and the triangle (a, b, c); 0 when
/// they intersect.
double segmentTriangleDistance(const Eigen::Vector3d& p, const Eigen::Vector3d& q,
                               const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                               const Eigen::Vector3d& c);

}  // namespace microsim::sim::collide
