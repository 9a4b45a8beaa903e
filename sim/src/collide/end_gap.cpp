#include "microsim/sim/collide/end_gap.h"

#include "microsim/sim/scene/scene_def.h"

#include <cmath>
#include <numbers>

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

/// The first node of `v`'s cut ring (the last ring) on `hull`: node index (ring·2 + hull)·P +
/// sector (mesh/vessel.h).
int cutRingFirst(const SceneVessel& v, VesselHull hull) {
  return v.firstNode + ((v.def.rings - 1) * 2 + static_cast<int>(hull)) * v.def.nodesPerRing;
}

/// The outer cut-ring node of `v` whose rest radial direction is nearest d.
int endGapLip(const SpringModel& model, const SceneVessel& v, const Vec3& d) {
  const int p = v.def.nodesPerRing;
  const Vec3 axis = v.def.direction.normalized();
  const auto rest = model.restPositions();
  const int firstOuterCut = cutRingFirst(v, VesselHull::Outer);
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
  const auto ends = severedEnds(vessels);
  if (ends[0] == nullptr || ends[1] == nullptr) return std::nullopt;

  // the stitch's direction: the mean radial direction of the pierce points about end 0's axis
  const Vec3 axis = ends[0]->def.direction.normalized();
  Vec3 d = Vec3::Zero();
  for (const Vec3& point : piercePoints) d += endGapRadial(point, ends[0]->def.origin, axis);
  if (d.norm() < 1e-12) {
    const int sector0 = cutRingFirst(*ends[0], VesselHull::Outer);
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

std::array<const SceneVessel*, 2> severedEnds(const std::vector<SceneVessel>& vessels) {
  std::array<const SceneVessel*, 2> ends{nullptr, nullptr};
  for (const SceneVessel& v : vessels)
    if (v.end == 0 || v.end == 1) ends[static_cast<std::size_t>(v.end)] = &v;
  return ends;
}

Vec3 cutRingLip(const SpringModel& model, const Points& x, const SceneVessel& v, const Vec3& d,
                VesselHull hull) {
  const int p = v.def.nodesPerRing;
  const int first = cutRingFirst(v, hull);
  const auto rest = model.restPositions();

  // d's angle in the ring's own frame: sector 0's rest direction, then right-handed about the axis
  const Vec3 axis = v.def.direction.normalized();
  const Vec3 e1 = endGapRadial(rest.col(first), v.def.origin, axis);
  const Vec3 e2 = axis.cross(e1);
  double turn = std::atan2(d.dot(e2), d.dot(e1)) / (2.0 * std::numbers::pi);
  if (turn < 0.0) turn += 1.0;

  // between the two sectors that flank it
  const double s = turn * p;
  const int j = static_cast<int>(std::floor(s)) % p;
  const double f = s - std::floor(s);
  return (1.0 - f) * x.col(first + j) + f * x.col(first + (j + 1) % p);
}

}  // namespace microsim::sim::collide
