#include "microsim/sim/tools/jaw_contact.h"

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

void appendJawContacts(const Forceps& forceps, const Points& x, const std::vector<int>& nodes,
                       const std::vector<std::uint8_t>& skip, double reach, double stiffness,
                       std::vector<PointSpring>& out) {
  for (const JawCapsule& c : jawCapsules(forceps)) {
    const Vec3 axis = c.heel - c.tip;
    const double length2 = axis.squaredNorm();
    if (!(length2 > 0.0)) continue;
    const Vec3 lo = c.tip.cwiseMin(c.heel).array() - (c.heelRadius + reach);
    const Vec3 hi = c.tip.cwiseMax(c.heel).array() + (c.heelRadius + reach);
    for (int i : nodes) {
      if (!skip.empty() && skip[static_cast<std::size_t>(i)]) continue;
      const Vec3 p = x.col(i);
      if ((p.array() < lo.array()).any() || (p.array() > hi.array()).any()) continue;
      const double s = std::clamp((p - c.tip).dot(axis) / length2, 0.0, 1.0);
      const Vec3 onAxis = c.tip + s * axis;
      const double radius = c.tipRadius + s * (c.heelRadius - c.tipRadius);
      const Vec3 away = p - onAxis;
      const double distance = away.norm();
      if (distance > radius + reach) continue;
      PointSpring spring;
      spring.nodes[0] = i;
      spring.weights[0] = 1.0;
      spring.anchor = onAxis;
      // a node on the axis itself is pushed out sideways, across the jaw
      Vec3 normal = distance > 1e-12 ? Vec3(away / distance) : axis.unitOrthogonal();
      spring.normal = normal;
      spring.gap = radius;
      spring.k = stiffness;
      out.push_back(spring);
    }
  }
}

}  // namespace microsim::sim::tools
