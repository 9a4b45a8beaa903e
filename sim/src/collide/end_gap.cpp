#include "microsim/sim/collide/end_gap.h"

#include "microsim/sim/scene/scene_def.h"

namespace microsim::sim::collide {

namespace {

/// The unit radial direction of p about the line through `origin` along unit `axis`, or
/// zero on the line.
Vec3 endGapRadial(const Vec3& p, const Vec3& origin, const Vec3& axis) {
  Vec3 r = p - origin;
  r -= r.dot(axis) * axis;
  const double n = r.norm();
  return n > 0.0 ? Vec3(r / n) : Vec3(Vec3::Zero());
}

/// The outer cut-ring node of `v` whose rest radial direction is nearest d.
int endGapLip(const SpringModel& model, const SceneVessel& v, const Vec3& d) {
  const int p = v.def.nodesPerRing;
  const Vec3 axis = v.def.direction.normalized();
  const auto rest = model.restPositions();
  // node index (ring·2 + hull)·P + sector, hull Outer = 1 (mesh/vessel.h)
  const int firstOuterCut = v.firstNode + ((v.def.rings - 1) * 2 + 1) * p;
  int best = firstOuterCut;
  double bestCos = -2.0;
  for (int j = 0; j < p; ++j) {
    const double c = endGapRadial(rest.col(firstOuterCut + j), v.def.origin, axis).dot(d);
    if (c > bestCos) {
      bestCos = c;
      best = firstOuterCut + j;
    }
  }
  return best;
}

}  // namespace

std::optional<EndGap> endGapAtStitch(const SpringModel& model, const Points& x,
                                     const std::vector<SceneVessel>& vessels,
                                     const std::vector<Vec3>& piercePoints) {
  const SceneVessel* ends[2] = {nullptr, nullptr};
  for (const SceneVessel& v : vessels)
    if (v.end == 0 || v.end == 1) ends[v.end] = &v;
  if (ends[0] == nullptr || ends[1] == nullptr) return std::nullopt;

  // the stitch's direction: the mean radial direction of the pierce points about end 0's axis
  const Vec3 axis = ends[0]->def.direction.normalized();
  Vec3 d = Vec3::Zero();
  for (const Vec3& point : piercePoints) d += endGapRadial(point, ends[0]->def.origin, axis);
  if (d.norm() < 1e-12) {
    const int sector0 = ends[0]->firstNode + ((ends[0]->def.rings - 1) * 2 + 1) * ends[0]->def.nodesPerRing;
    d = endGapRadial(model.restPositions().col(sector0), ends[0]->def.origin, axis);
  }
  d.normalize();

  // each end's lip at that angle, and their distance
  EndGap g;
  g.direction = d;
  g.node0 = endGapLip(model, *ends[0], d);
  g.node1 = endGapLip(model, *ends[1], d);
  g.gap = (x.col(g.node1) - x.col(g.node0)).norm();
  g.restGap = (model.restPositions().col(g.node1) - model.restPositions().col(g.node0)).norm();
  return g;
}

}  // namespace microsim::sim::collide
