#include "microsim/sim/collide/point_triangle.h"

#include "microsim/sim/collide/segment_segment.h"

#include <Eigen/Geometry>

#include <algorithm>

namespace microsim::sim::collide {

using Eigen::Vector3d;

namespace {

PointTriangleClosest make(const Vector3d& p, double u, double v, double w, const Vector3d& a,
                          const Vector3d& b, const Vector3d& c) {
  PointTriangleClosest out;
  out.barycentric = Vector3d(u, v, w);
  out.point = u * a + v * b + w * c;
  out.distance = (p - out.point).norm();
  return out;
}

// the closest over the three edges, for triangles without a face region
PointTriangleClosest closestOverEdges(const Vector3d& p, const Vector3d& a, const Vector3d& b,
                                      const Vector3d& c) {
  const double tab = closestParameterOnSegment(p, a, b);
  const double tbc = closestParameterOnSegment(p, b, c);
  const double tca = closestParameterOnSegment(p, c, a);
  PointTriangleClosest best = make(p, 1.0 - tab, tab, 0.0, a, b, c);
  const PointTriangleClosest onBc = make(p, 0.0, 1.0 - tbc, tbc, a, b, c);
  if (onBc.distance < best.distance) best = onBc;
  const PointTriangleClosest onCa = make(p, tca, 0.0, 1.0 - tca, a, b, c);
  if (onCa.distance < best.distance) best = onCa;
  return best;
}

}  // namespace

PointTriangleClosest closestPointTriangle(const Vector3d& p, const Vector3d& a, const Vector3d& b,
                                          const Vector3d& c) {
  const Vector3d ab = b - a;
  const Vector3d ac = c - a;
  const double n2 = ab.cross(ac).squaredNorm();
  const double scale2 = std::max(ab.squaredNorm(), ac.squaredNorm());
  if (n2 <= 1e-24 * scale2 * scale2) return closestOverEdges(p, a, b, c);

  // vertex region a
  const Vector3d ap = p - a;
  const double d1 = ab.dot(ap);
  const double d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return make(p, 1.0, 0.0, 0.0, a, b, c);

  // vertex region b
  const Vector3d bp = p - b;
  const double d3 = ab.dot(bp);
  const double d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return make(p, 0.0, 1.0, 0.0, a, b, c);

  // edge region ab
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double v = d1 / (d1 - d3);
    return make(p, 1.0 - v, v, 0.0, a, b, c);
  }

  // vertex region c
  const Vector3d cp = p - c;
  const double d5 = ab.dot(cp);
  const double d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return make(p, 0.0, 0.0, 1.0, a, b, c);

  // edge region ac
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double w = d2 / (d2 - d6);
    return make(p, 1.0 - w, 0.0, w, a, b, c);
  }

  // edge region bc
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return make(p, 0.0, 1.0 - w, w, a, b, c);
  }

  // face region
  const double denom = 1.0 / (va + vb + vc);
  const double v = vb * denom;
  const double w = vc * denom;
  return make(p, 1.0 - v - w, v, w, a, b, c);
}

}  // namespace microsim::sim::collide
