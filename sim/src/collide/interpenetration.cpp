#include "microsim/sim/collide/interpenetration.h"

#include "microsim/sim/scene/scene_def.h"

#include <cmath>
#include <numbers>

namespace microsim::sim::collide {

std::vector<ClosedBody> vesselBodies(const std::vector<SceneVessel>& vessels) {
  std::vector<ClosedBody> bodies;
  bodies.reserve(vessels.size());
  for (const SceneVessel& v : vessels)
    bodies.push_back({v.firstNode, 2 * v.def.rings * v.def.nodesPerRing,
                      {v.outerSurface, v.innerSurface, v.clampedEnd, v.cutEnd}});
  return bodies;
}

double windingNumber(const SpringModel& model, const Points& x, const ClosedBody& body, const Vec3& p) {
  const auto& triangles = model.triangles();
  double solidAngle = 0.0;
  for (const TriangleRange& range : body.shell)
    for (int t = range.begin; t < range.end; ++t) {
      const auto& tri = triangles[static_cast<std::size_t>(t)];
      const Vec3 a = x.col(tri[0]) - p;
      const Vec3 b = x.col(tri[1]) - p;
      const Vec3 c = x.col(tri[2]) - p;
      const double la = a.norm(), lb = b.norm(), lc = c.norm();
      const double numerator = a.dot(b.cross(c));
      const double denominator = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
      solidAngle += 2.0 * std::atan2(numerator, denominator);
    }
  return solidAngle / (4.0 * std::numbers::pi);
}

Interpenetration interpenetration(const SpringModel& model, const Points& x,
                                  const std::vector<ClosedBody>& bodies) {
  Interpenetration out;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const ClosedBody& body = bodies[b];
    if (body.nodeCount <= 0) continue;

    // the body's box, from its nodes where they are now
    const auto own = x.middleCols(body.firstNode, body.nodeCount);
    const Vec3 lo = own.rowwise().minCoeff();
    const Vec3 hi = own.rowwise().maxCoeff();

    // every other body's node in the box, tested by the winding number
    for (std::size_t o = 0; o < bodies.size(); ++o) {
      if (o == b) continue;
      for (int i = bodies[o].firstNode; i < bodies[o].firstNode + bodies[o].nodeCount; ++i) {
        const Vec3 p = x.col(i);
        if ((p.array() < lo.array()).any() || (p.array() > hi.array()).any()) continue;
        if (std::abs(windingNumber(model, x, body, p)) > 0.5)
          out.pairs.push_back({i, static_cast<int>(b)});
      }
    }
  }
  out.count = static_cast<int>(out.pairs.size());
  return out;
}

Interpenetration interpenetration(const SpringModel& model, const Points& x,
                                  const std::vector<SceneVessel>& vessels) {
  return interpenetration(model, x, vesselBodies(vessels));
}

}  // namespace microsim::sim::collide
