#pragma once
// Closest point of a triangle to a point (grabbing: tool tip against tissue faces; and the
// vertex–face part of the triangle distances).
//
// Minimises |p − (u a + v b + w c)| over u, v, w ≥ 0, u + v + w = 1 by Voronoi regions
// (Ericson, Real-Time Collision Detection §5.1.5): three vertex regions, three edge
// regions, the face. A zero-area triangle (collinear or coincident corners) has no face
// region; its closest point is the closest over its three edges.
//
// Units: millimetres.

#include <Eigen/Core>

namespace microsim::sim::collide {

struct PointTriangleClosest {
  Eigen::Vector3d point;       ///< closest point on the triangle, mm
  Eigen::Vector3d barycentric; ///< (u, v, w) with point = u a + v b + w c, each ≥ 0, sum 1
  double distance = 0.0;       ///< |p − point|, mm
};

PointTriangleClosest closestPointTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                          const Eigen::Vector3d& b, const Eigen::Vector3d& c);

}  // namespace microsim::sim::collide
