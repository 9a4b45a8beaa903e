#include "microsim/sim/collide/triangle_triangle.h"

#include "microsim/sim/collide/point_triangle.h"
#include "microsim/sim/collide/segment_segment.h"
#include "microsim/sim/collide/segment_triangle.h"
#include "tolerance.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <limits>

namespace microsim::sim::collide {

using Eigen::Vector3d;

namespace {

// all three corners clearly on one side of the plane of (a, b, c)
bool oneSide(const Vector3d& p0, const Vector3d& p1, const Vector3d& p2, const Vector3d& a,
             const Vector3d& b, const Vector3d& c) {
  const Vector3d n = (b - a).cross(c - a);
  const double d0 = n.dot(p0 - a);
  const double d1 = n.dot(p1 - a);
  const double d2 = n.dot(p2 - a);
  const double tol = kRelativeTolerance * coordinateScale({&p0, &p1, &p2, &a, &b, &c}) * n.norm();
  return (d0 > tol && d1 > tol && d2 > tol) || (d0 < -tol && d1 < -tol && d2 < -tol);
}

}  // namespace

bool trianglesIntersect(const Vector3d& p0, const Vector3d& p1, const Vector3d& p2,
                        const Vector3d& q0, const Vector3d& q1, const Vector3d& q2) {
  // plane rejection both ways
  if (oneSide(p0, p1, p2, q0, q1, q2) || oneSide(q0, q1, q2, p0, p1, p2)) return false;

  // an edge of one through the other
  return intersectSegmentTriangle(p0, p1, q0, q1, q2) ||
         intersectSegmentTriangle(p1, p2, q0, q1, q2) ||
         intersectSegmentTriangle(p2, p0, q0, q1, q2) ||
         intersectSegmentTriangle(q0, q1, p0, p1, p2) ||
         intersectSegmentTriangle(q1, q2, p0, p1, p2) ||
         intersectSegmentTriangle(q2, q0, p0, p1, p2);
}

double triangleTriangleDistance(const Vector3d& p0, const Vector3d& p1, const Vector3d& p2,
                                const Vector3d& q0, const Vector3d& q1, const Vector3d& q2) {
  if (trianglesIntersect(p0, p1, p2, q0, q1, q2)) return 0.0;
  const Vector3d* ps[3] = {&p0, &p1, &p2};
  const Vector3d* qs[3] = {&q0, &q1, &q2};
  double d = std::numeric_limits<double>::infinity();

  // edge against edge
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      d = std::min(d, closestSegmentSegment(*ps[i], *ps[(i + 1) % 3], *qs[j], *qs[(j + 1) % 3])
                          .distance);

  // corner against face
  for (int i = 0; i < 3; ++i) {
    d = std::min(d, closestPointTriangle(*ps[i], q0, q1, q2).distance);
    d = std::min(d, closestPointTriangle(*qs[i], p0, p1, p2).distance);
  }
  return d;
}

}  // namespace microsim::sim::collide
