#include "microsim/sim/collide/segment_triangle.h"

#include "microsim/sim/collide/point_triangle.h"
#include "microsim/sim/collide/segment_segment.h"
#include "tolerance.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace microsim::sim::collide {

using Eigen::Vector3d;

namespace {

bool sameSign(double x, double y, double z) {
  return (x >= 0.0 && y >= 0.0 && z >= 0.0) || (x <= 0.0 && y <= 0.0 && z <= 0.0);
}

// coplanar segment or zero-area triangle: p inside, else the first edge crossing
std::optional<SegmentTriangleHit> inPlaneHit(const Vector3d& p, const Vector3d& q,
                                             const Vector3d& a, const Vector3d& b,
                                             const Vector3d& c, const Vector3d& n) {
  const double n2 = n.squaredNorm();
  if (n2 > 0.0) {
    const double u = (c - b).cross(p - b).dot(n);
    const double v = (a - c).cross(p - c).dot(n);
    const double w = (b - a).cross(p - a).dot(n);
    if (u >= 0.0 && v >= 0.0 && w >= 0.0) {
      const double sum = u + v + w;
      return SegmentTriangleHit{0.0, p, Vector3d(u, v, w) / sum};
    }
  }

  // tolerance for "the segments meet", relative to the coordinates' scale
  const double tolerance = kRelativeTolerance * coordinateScale({&p, &q, &a, &b, &c});

  std::optional<SegmentTriangleHit> best;
  const Vector3d* corners[3] = {&a, &b, &c};
  for (int e = 0; e < 3; ++e) {
    const Vector3d& from = *corners[e];
    const Vector3d& to = *corners[(e + 1) % 3];
    const SegmentClosest close = closestSegmentSegment(p, q, from, to);
    if (close.distance > tolerance) continue;
    if (best && best->t <= close.s) continue;
    Vector3d bary = Vector3d::Zero();
    bary[e] = 1.0 - close.t;
    bary[(e + 1) % 3] = close.t;
    best = SegmentTriangleHit{close.s, close.onSecond, bary};
  }
  return best;
}

}  // namespace

std::optional<SegmentTriangleHit> intersectSegmentTriangle(const Vector3d& p, const Vector3d& q,
                                                           const Vector3d& a, const Vector3d& b,
                                                           const Vector3d& c) {
  const Vector3d n = (b - a).cross(c - a);
  const double sp = n.dot(p - a);
  const double sq = n.dot(q - a);
  const double onPlane = kRelativeTolerance * coordinateScale({&p, &q, &a, &b, &c}) * n.norm();

  // both ends clearly on one side of the plane
  if ((sp > onPlane && sq > onPlane) || (sp < -onPlane && sq < -onPlane)) return std::nullopt;
  if (n.squaredNorm() == 0.0 || (std::abs(sp) <= onPlane && std::abs(sq) <= onPlane))
    return inPlaneHit(p, q, a, b, c, n);

  // the line through p and q against the three edges, by signed volumes
  const Vector3d pq = q - p;
  const Vector3d pa = a - p;
  const Vector3d pb = b - p;
  const Vector3d pc = c - p;
  const double u = pq.cross(pc).dot(pb);
  const double v = pq.cross(pa).dot(pc);
  const double w = pq.cross(pb).dot(pa);
  if (!sameSign(u, v, w)) return std::nullopt;
  const double sum = u + v + w;
  if (sum == 0.0) return inPlaneHit(p, q, a, b, c, n);

  // the crossing of the plane
  SegmentTriangleHit hit;
  hit.barycentric = Vector3d(u, v, w) / sum;
  hit.point = hit.barycentric[0] * a + hit.barycentric[1] * b + hit.barycentric[2] * c;
  hit.t = sp == sq ? 0.0 : std::clamp(sp / (sp - sq), 0.0, 1.0);
  return hit;
}

double segmentTriangleDistance(const Vector3d& p, const Vector3d& q, const Vector3d& a,
                               const Vector3d& b, const Vector3d& c) {
  if (intersectSegmentTriangle(p, q, a, b, c)) return 0.0;
  double d = std::min(closestPointTriangle(p, a, b, c).distance,
                      closestPointTriangle(q, a, b, c).distance);
  d = std::min(d, closestSegmentSegment(p, q, a, b).distance);
  d = std::min(d, closestSegmentSegment(p, q, b, c).distance);
  d = std::min(d, closestSegmentSegment(p, q, c, a).distance);
  return d;
}

}  // namespace microsim::sim::collide
