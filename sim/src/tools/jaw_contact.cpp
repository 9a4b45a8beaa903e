#include "microsim/sim/tools/jaw_contact.h"

#include "microsim/sim/collide/point_triangle.h"

#include <algorithm>
#include <cmath>

namespace microsim::sim::tools {

std::array<double, 2> jawRadii(const ForcepsDef& def) {
  const double length = jawLength(def);
  std::array<double, 2> radii{0.0, 0.0};
  for (Eigen::Index v = 0; v < def.jawVertices.cols(); ++v) {
    const Vec3 p = def.jawVertices.col(v);
    const double off = std::hypot(p.y(), p.z());
    if (p.x() <= 0.1 * length) radii[0] = std::max(radii[0], off);
    if (p.x() >= 0.9 * length) radii[1] = std::max(radii[1], off);
  }
  if (radii[1] < radii[0]) radii[1] = radii[0];
  return radii;
}

std::array<JawCapsule, 2> jawCapsules(const Forceps& forceps) {
  const std::array<Eigen::Isometry3d, 2> poses = jawPoses(forceps.def(), forceps.pose(), forceps.closure());
  const std::array<double, 2> radii = jawRadii(forceps.def());
  const double length = jawLength(forceps.def());
  std::array<JawCapsule, 2> capsules;
  for (std::size_t j = 0; j < 2; ++j) {
    capsules[j].tip = poses[j] * Vec3::Zero();
    capsules[j].heel = poses[j] * Vec3(length, 0.0, 0.0);
    capsules[j].tipRadius = radii[0];
    capsules[j].heelRadius = radii[1];
  }
  return capsules;
}

void appendJawContacts(const Forceps& forceps, const SpringModel& tissue, const Points& x,
                       const std::vector<std::uint8_t>& skip, double reach, double stiffness,
                       std::vector<PointSpring>& out) {
  for (const JawCapsule& c : jawCapsules(forceps)) {
    const Vec3 axis = c.heel - c.tip;
    const double length2 = axis.squaredNorm();
    if (!(length2 > 0.0)) continue;
    const auto onAxis = [&](const Vec3& p) { return std::clamp((p - c.tip).dot(axis) / length2, 0.0, 1.0); };
    const Vec3 lo = c.tip.cwiseMin(c.heel).array() - (c.heelRadius + reach);
    const Vec3 hi = c.tip.cwiseMax(c.heel).array() + (c.heelRadius + reach);
    for (const auto& t : tissue.triangles()) {
      if (!skip.empty() && (skip[static_cast<std::size_t>(t[0])] || skip[static_cast<std::size_t>(t[1])] ||
                            skip[static_cast<std::size_t>(t[2])]))
        continue;
      const Vec3 a = x.col(t[0]), b = x.col(t[1]), d = x.col(t[2]);
      if ((a.cwiseMax(b).cwiseMax(d).array() < lo.array()).any() ||
          (a.cwiseMin(b).cwiseMin(d).array() > hi.array()).any())
        continue;
      // the closest points of the axis and the face, by alternating projections (both convex)
      double s = onAxis((a + b + d) / 3.0);
      collide::PointTriangleClosest q{};
      for (int k = 0; k < 4; ++k) {
        q = collide::closestPointTriangle(c.tip + s * axis, a, b, d);
        s = onAxis(q.point);
      }
      const Vec3 anchor = c.tip + s * axis;
      const double radius = c.tipRadius + s * (c.heelRadius - c.tipRadius);
      if ((q.point - anchor).norm() > radius + reach) continue;
      const Vec3 faceNormal = (b - a).cross(d - a);
      if (!(faceNormal.norm() > 0.0)) continue;
      // only a face the jaw is in front of: the wall's far side (the lumen's face under the
      // top of the wall) is reached through the near one, never directly
      if (faceNormal.dot(anchor - q.point) < 0.0) continue;
      PointSpring spring;
      for (std::size_t v = 0; v < 3; ++v) {
        spring.nodes[v] = t[v];
        spring.weights[v] = q.barycentric[static_cast<Eigen::Index>(v)];
      }
      spring.anchor = anchor;
      // the jaw pushes the face straight away from its axis, the way the face lies from it:
      // every face round a jaw is pushed outward from the jaw, never one against another (a
      // jaw tip opened into the corner of a cut end took the cut face's and the outer face's
      // normals, which pushed the rim against itself and swung its stretch past 50 % from one
      // step to the next); a face the axis runs through is pushed back into its wall
      const Vec3 away = q.point - anchor;
      spring.normal =
          away.norm() > 1e-9 * radius ? Vec3(away.normalized()) : Vec3(-faceNormal.normalized());
      spring.gap = radius;
      spring.k = stiffness;
      out.push_back(spring);
    }
  }
}

}  // namespace microsim::sim::tools
