#include "microsim/sim/collide/segment_segment.h"

#include <algorithm>

namespace microsim::sim::collide {

using Eigen::Vector3d;

double closestParameterOnSegment(const Vector3d& p, const Vector3d& a, const Vector3d& b) {
  const Vector3d ab = b - a;
  const double len2 = ab.squaredNorm();
  if (len2 <= 0.0) return 0.0;
  return std::clamp((p - a).dot(ab) / len2, 0.0, 1.0);
}

SegmentClosest closestSegmentSegment(const Vector3d& p0, const Vector3d& p1, const Vector3d& q0,
                                     const Vector3d& q1) {
  const Vector3d d1 = p1 - p0;
  const Vector3d d2 = q1 - q0;
  const Vector3d r = p0 - q0;
  const double a = d1.squaredNorm();
  const double e = d2.squaredNorm();
  const double f = d2.dot(r);
  double s = 0.0;
  double t = 0.0;

  if (a <= 0.0 && e <= 0.0) {
    // both are points
  } else if (a <= 0.0) {
    // first is a point
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = d1.dot(r);
    if (e <= 0.0) {
      // second is a point
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      // general case: the line optimum clamped to [0, 1], then t from s and s again from t
      const double b = d1.dot(d2);
      const double denom = a * e - b * b;
      s = denom > 1e-14 * a * e ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0.0) {
        t = 0.0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1.0) {
        t = 1.0;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }

  SegmentClosest out;
  out.s = s;
  out.t = t;
  out.onFirst = p0 + s * d1;
  out.onSecond = q0 + t * d2;
  out.distance = (out.onFirst - out.onSecond).norm();
  return out;
}

}  // namespace microsim::sim::collide
