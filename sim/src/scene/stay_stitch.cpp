#include "microsim/sim/scene/stay_stitch.h"

#include "microsim/sim/collide/point_triangle.h"
#include "microsim/sim/scene/circumference_frame.h"
#include "microsim/sim/scene/scene_def.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace microsim::sim {

namespace {

// the hole on the surface `range` nearest `point`: its face, barycentric and point
suture::Pierce holeOn(const SpringModel& tissue, const TriangleRange& range, const Vec3& point) {
  const Points& x = tissue.restPositions();
  suture::Pierce best;
  double nearest = std::numeric_limits<double>::infinity();
  for (int f = range.begin; f < range.end; ++f) {
    const auto& t = tissue.triangles()[static_cast<std::size_t>(f)];
    const collide::PointTriangleClosest c =
        collide::closestPointTriangle(point, x.col(t[0]), x.col(t[1]), x.col(t[2]));
    if (c.distance >= nearest) continue;
    nearest = c.distance;
    best.face = f;
    best.barycentric = c.barycentric;
    best.point = c.point;
  }
  return best;
}

}  // namespace

std::variant<LaidStayStitch, StayStitchError> layStayStitch(const SceneDef& def,
                                                            const StayStitchDef& stitch) {
  if (!def.needle) return StayStitchError::NoNeedle;
  const SceneVessel* ends[2] = {nullptr, nullptr};
  for (const SceneVessel& v : def.vessels)
    if (v.end == 0 || v.end == 1) ends[v.end] = &v;
  if (!ends[0] || !ends[1] || ends[0]->object != ends[1]->object)
    return StayStitchError::NoSeveredVessel;

  const suture::SutureModel model(def.needle->suture);
  const int n = model.swage();
  const int last = model.nodeCount() - 1;
  const double link = model.rest(n);  // every thread link has the same rest length
  const VesselDef& v0 = ends[0]->def;
  const VesselDef& v1 = ends[1]->def;
  const double wall = v0.wallThickness;
  // each wall crossed obliquely by the fewest links longer together than it is thick
  const int wallLinks = static_cast<int>(std::floor(wall / link)) + 1;
  const double crossing = wallLinks * link;
  const double bite = stitch.biteWalls * wall;
  if (!(bite > 0.0) || bite >= v0.length) return StayStitchError::BiteOutsideTheEnd;

  // the angle frame of attempt.h, and the radial and circumferential directions there
  const Vec3 a0 = v0.direction.normalized();
  const Vec3 a1 = v1.direction.normalized();
  const Vec3 cut0 = v0.origin + v0.length * a0;
  const Vec3 cut1 = v1.origin + v1.length * a1;
  const Vec3 zero = circumferenceZero(a0, def.camera.eye - cut0);
  const double angle = stitch.angleDeg * std::numbers::pi / 180.0;
  const Vec3 radial = std::cos(angle) * zero + std::sin(angle) * a0.cross(zero);
  const Vec3 around = a0.cross(radial);

  // the holes on the faceted walls, a few µm inside the cylinders the path is planned on: each
  // wall's crossing is laid between points already on its faces, its depth measured there,
  // so that its links start at their rest length (on a finer thread a few µm is a fifth of one)
  const SpringModel& tissue = def.tissue.model;
  const auto onFace = [&](const TriangleRange& surface, const Vec3& p) {
    return holeOn(tissue, surface, p).point;
  };
  // from `hole` on one surface to the other surface, `way` along the axis: the crossing's end
  const auto crossWall = [&](const Vec3& hole, const TriangleRange& other, const Vec3& below,
                             const Vec3& axis, const Vec3& way) {
    Vec3 depth = onFace(other, below) - hole;
    depth -= depth.dot(axis) * axis;
    const double run = std::sqrt(std::max(0.0, crossing * crossing - depth.squaredNorm()));
    return onFace(other, hole + run * way + depth);
  };
  const Vec3 out0 = onFace(ends[0]->outerSurface, cut0 - bite * a0 + v0.radius * radial);
  const Vec3 in0 = crossWall(out0, ends[0]->innerSurface, out0 - wall * radial, a0, a0);
  // across the lumen in whole links, to end 1's inner surface
  const double innerBite0 = (cut0 - in0).dot(a0);
  const double gap = (cut1 - cut0).norm();
  const int lumenLinks = std::max(1, static_cast<int>(std::ceil((gap + 2.0 * innerBite0) / link)));
  const double innerBite1 = lumenLinks * link - gap - innerBite0;
  if (innerBite1 + std::sqrt(crossing * crossing - wall * wall) >= v1.length)
    return StayStitchError::BiteOutsideTheEnd;
  const Vec3 in1 = onFace(ends[1]->innerSurface,
                          cut1 - innerBite1 * a1 + (v1.radius - v1.wallThickness) * radial);
  const Vec3 out1 = crossWall(in1, ends[1]->outerSurface, in1 + v1.wallThickness * radial, a1, -a1);

  // node numbers: the tail from N, the holes, the long end down to the swage
  const int tailLinks = std::max(2, static_cast<int>(std::lround(stitch.tailMm / link)));
  const int hole0 = last - tailLinks;
  const int hole1 = hole0 - wallLinks;
  const int hole2 = hole1 - lumenLinks;
  const int hole3 = hole2 - wallLinks;
  if (hole3 - n < 2) return StayStitchError::ThreadTooShort;

  LaidStayStitch laid;
  laid.shape.resize(3, model.nodeCount());
  Points& x = laid.shape;
  // both free lengths leave the wall straight out, then lie clear of the vessel where the
  // microscope sees them: the tail away from the gap and toward the circumference; the long
  // end first toward the circumference (about 1.6 mm, off the vessel), then along it away from
  // the gap, so the needle lies inside the field of view rather than 4–5 mm down the vessel
  const Vec3 tailWay = (-a0 + 0.6 * around).normalized();
  const Vec3 longWay = -a1;
  const int outLinks = std::min(hole3 - 1 - n, static_cast<int>(std::lround(1.6 / link)));
  // through each wall on a straight line from hole to hole
  for (int j = 0; j <= wallLinks; ++j) {
    const double t = static_cast<double>(j) / wallLinks;
    x.col(hole0 - j) = out0 + t * (in0 - out0);
    x.col(hole2 - j) = in1 + t * (out1 - in1);
  }
  for (int i = hole0 + 1; i <= last; ++i)
    x.col(i) = out0 + link * radial + (i - hole0 - 1) * link * tailWay;
  for (int j = 0; j <= lumenLinks; ++j)
    x.col(hole1 - j) = in0 + (static_cast<double>(j) / lumenLinks) * (in1 - in0);
  const Vec3 corner = out1 + link * radial + outLinks * link * around;
  for (int i = hole3 - 1; i >= n; --i) {
    const int along = hole3 - 1 - i;
    x.col(i) = along <= outLinks ? Vec3(out1 + link * radial + along * link * around)
                                 : Vec3(corner + (along - outLinks) * link * longWay);
  }

  // the needle, flat (its plane ⟂ the radial direction), the thread leaving its swage along
  // the swage tangent toward the stitch
  const suture::Points& rest = model.restPositions();
  const Vec3 swageTangent = (rest.col(n + 1) - rest.col(n)).normalized();
  const Vec3 needleNormal = Vec3::UnitZ();
  Eigen::Matrix3d from;
  from << swageTangent, needleNormal, swageTangent.cross(needleNormal);
  const Vec3 threadWay = (x.col(n + 1) - x.col(n)).normalized();
  const Vec3 up = (radial - radial.dot(threadWay) * threadWay).normalized();
  Eigen::Matrix3d to;
  to << threadWay, up, threadWay.cross(up);
  const Eigen::Matrix3d rotation = to * from.transpose();
  const Vec3 swage = x.col(n);
  for (int i = 0; i < n; ++i) x.col(i) = swage + rotation * (rest.col(i) - rest.col(n));

  // each node on its hole, the hole's face and barycentrics recorded
  const struct {
    int node;
    const TriangleRange& surface;
  } holes[4] = {{hole0, ends[0]->outerSurface},
                {hole1, ends[0]->innerSurface},
                {hole2, ends[1]->innerSurface},
                {hole3, ends[1]->outerSurface}};
  for (const auto& h : holes) {
    suture::Pierce p = holeOn(tissue, h.surface, x.col(h.node));
    p.node = h.node;
    x.col(h.node) = p.point;
    laid.pierces.push_back(p);
  }
  return laid;
}

}  // namespace microsim::sim
