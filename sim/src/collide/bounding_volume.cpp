#include "microsim/sim/collide/bounding_volume.h"

#include <Eigen/Geometry>

#include <cmath>

namespace microsim::sim::collide {

namespace {

// twice the exact tests' tolerance (tolerance.h), so a volume never rejects what they accept
constexpr double kInflate = 2e-12;

// the radius that reaches every given point from the centre, slightly inflated; every point
// lies within r of the centre, so |centre|∞ + r bounds the coordinates' scale
double reach(const Vec3& centre, std::initializer_list<const Vec3*> points) {
  double r2 = 0.0;
  for (const Vec3* p : points) r2 = std::max(r2, (*p - centre).squaredNorm());
  const double r = std::sqrt(r2);
  return r + kInflate * (2.0 * r + centre.cwiseAbs().maxCoeff());
}

}  // namespace

Sphere fitSphere(const Vec3& a, const Vec3& b) {
  const Vec3 centre = 0.5 * (a + b);
  return {centre, reach(centre, {&a, &b})};
}

Sphere fitSphere(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a;
  const Vec3 ac = c - a;
  const Vec3 bc = c - b;
  const Vec3 n = ab.cross(ac);
  const double n2 = n.squaredNorm();
  const double ab2 = ab.squaredNorm();
  const double ac2 = ac.squaredNorm();
  const double bc2 = bc.squaredNorm();
  const double longest2 = std::max({ab2, ac2, bc2});

  // obtuse or degenerate: the sphere on the longest edge
  const bool obtuse = ab.dot(ac) < 0.0 || (-ab).dot(bc) < 0.0 || ac.dot(bc) < 0.0;
  if (obtuse || n2 <= 1e-24 * longest2 * longest2) {
    if (ab2 >= ac2 && ab2 >= bc2) return {0.5 * (a + b), reach(0.5 * (a + b), {&a, &b, &c})};
    if (ac2 >= bc2) return {0.5 * (a + c), reach(0.5 * (a + c), {&a, &b, &c})};
    return {0.5 * (b + c), reach(0.5 * (b + c), {&a, &b, &c})};
  }

  // acute or right: the circumsphere
  const Vec3 offset = (ac2 * n.cross(ab) + ab2 * ac.cross(n)) / (2.0 * n2);
  const Vec3 centre = a + offset;
  return {centre, reach(centre, {&a, &b, &c})};
}

Sphere mergeSpheres(const Sphere& s, const Sphere& t) {
  const Vec3 delta = t.centre - s.centre;
  const double d = delta.norm();
  if (d + t.radius <= s.radius) return s;
  if (d + s.radius <= t.radius) return t;
  const double r = 0.5 * (d + s.radius + t.radius);
  const Vec3 centre = s.centre + ((r - s.radius) / d) * delta;
  const double scale = std::max(centre.cwiseAbs().maxCoeff(), r);
  return {centre, r + kInflate * scale};
}

Aabb fitAabb(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 lo = a.cwiseMin(b).cwiseMin(c);
  const Vec3 hi = a.cwiseMax(b).cwiseMax(c);
  const double grow = kInflate * std::max(lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff());
  return {lo.array() - grow, hi.array() + grow};
}

Aabb fitAabb(const Vec3& a, const Vec3& b) {
  const Vec3 lo = a.cwiseMin(b);
  const Vec3 hi = a.cwiseMax(b);
  const double grow = kInflate * std::max(lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff());
  return {lo.array() - grow, hi.array() + grow};
}

}  // namespace microsim::sim::collide
