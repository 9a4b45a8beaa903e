#pragma once
// Closest points of two segments (suture self-contact: link against link).
//
// Segments P(s) = p0 + s (p1 − p0), Q(t) = q0 + t (q1 − q0), s, t ∈ [0, 1]. Minimises
// |P(s) − Q(t)|² over the unit square (Ericson, Real-Time Collision Detection §5.1.9): the
// unconstrained optimum of the 2×2 normal equations, clamped to the square edge by edge.
// Degenerate inputs are exact cases, not errors: a zero-length segment is a point, parallel
// segments take s = 0 (or the clamp of the overlap) and return one of the closest pairs.
//
// Units: millimetres.

#include <Eigen/Core>

namespace microsim::sim::collide {

struct SegmentClosest {
  double s = 0.0;              ///< parameter on the first segment, [0, 1]
  double t = 0.0;              ///< parameter on the second segment, [0, 1]
  Eigen::Vector3d onFirst;     ///< P(s), mm
  Eigen::Vector3d onSecond;    ///< Q(t), mm
  double distance = 0.0;       ///< |P(s) − Q(t)|, mm
};

SegmentClosest closestSegmentSegment(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                     const Eigen::Vector3d& q0, const Eigen::Vector3d& q1);

/// Closest point of the segment (a, b) to p: parameter in [0, 1].
double closestParameterOnSegment(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                 const Eigen::Vector3d& b);

}  // namespace microsim::sim::collide
