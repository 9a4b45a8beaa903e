#include "microsim/sim/tools/jaw_grasp.h"

#include "microsim/sim/collide/segment_segment.h"
#include "microsim/sim/tools/forceps.h"

#include <algorithm>
#include <cmath>

namespace microsim::sim::tools {

namespace {

/// Tangent planes that stand in for the arc the tips run along.
constexpr int kArcTangents = 5;

/// A face part smaller than this share of its face is a touch along an edge, not a grasp.
constexpr double kMinimumFaceShare = 1e-9;

GraspPlane planeThrough(const Vec3& normal, const Vec3& point, double margin) {
  const Vec3 n = normal.normalized();
  return {n, n.dot(point) + margin};
}

}  // namespace

std::array<double, 2> jawHalfWidths(const ForcepsDef& def) {
  const double length = jawLength(def);
  std::array<double, 2> widths{0.0, 0.0};
  for (Eigen::Index v = 0; v < def.jawVertices.cols(); ++v) {
    const Vec3 p = def.jawVertices.col(v);
    if (p.x() <= 0.1 * length) widths[0] = std::max(widths[0], std::abs(p.z()));
    if (p.x() >= 0.9 * length) widths[1] = std::max(widths[1], std::abs(p.z()));
  }
  return widths;
}

GraspRegion graspRegion(const ForcepsDef& def, const Eigen::Isometry3d& pose, double closure,
                        double margin) {
  GraspRegion region;
  const double length = jawLength(def);
  const double theta = jawAngle(def, closure);
  const Vec3 ex = pose.linear().col(0);
  const Vec3 ey = pose.linear().col(1);
  const Vec3 ez = pose.linear().col(2);
  const Vec3 origin = pose.translation();
  const Vec3 hinge = pose * Vec3(length, 0.0, 0.0);
  region.axisTip = origin;
  region.axisHeel = hinge;

  // the gripping faces: each jaw frame's y = 0 plane, its +y (towards the jaw's body) outward
  const std::array<Eigen::Isometry3d, 2> jaws = jawPoses(def, pose, closure);
  for (const Eigen::Isometry3d& jaw : jaws)
    region.planes.push_back(planeThrough(jaw.linear().col(1), jaw.translation(), margin));

  // the jaws' width out of their plane, |z| ≤ w_tip + (w_heel − w_tip) x / L
  const std::array<double, 2> w = jawHalfWidths(def);
  const double slope = length > 0.0 ? (w[1] - w[0]) / length : 0.0;
  for (const double side : {1.0, -1.0}) {
    const Vec3 n = side * ez - slope * ex;
    region.planes.push_back({n.normalized(), (n.dot(origin) + w[0]) / n.norm() + margin});
  }

  // the arc the tips run along, by planes tangent to it between the two jaws' axes
  for (int k = 0; k < kArcTangents; ++k) {
    const double phi = theta * (2.0 * k / (kArcTangents - 1) - 1.0);
    const Vec3 out = -std::cos(phi) * ex + std::sin(phi) * ey;
    region.planes.push_back({out, out.dot(hinge) + length + margin});
  }

  // a box around it all: the sector's corners, widened by the jaws' width, the margin and
  // the tangents' corners beyond the arc
  const double beyond = length * (1.0 / std::cos(theta / (kArcTangents - 1)) - 1.0);
  const double widen = std::max(w[0], w[1]) + margin + beyond;
  region.boxLow = hinge.cwiseMin(origin);
  region.boxHigh = hinge.cwiseMax(origin);
  for (const Eigen::Isometry3d& jaw : jaws) {
    region.boxLow = region.boxLow.cwiseMin(jaw.translation());
    region.boxHigh = region.boxHigh.cwiseMax(jaw.translation());
  }
  region.boxLow.array() -= widen;
  region.boxHigh.array() += widen;
  return region;
}

bool insideGraspRegion(const GraspRegion& region, const Vec3& p) {
  return std::all_of(region.planes.begin(), region.planes.end(),
                     [&](const GraspPlane& h) { return h.normal.dot(p) <= h.offset; });
}

std::vector<FaceGrasp> facesBetweenJaws(const GraspRegion& region, const SpringModel& tissue,
                                        const Points& x, const std::vector<std::uint8_t>& skip) {
  std::vector<FaceGrasp> out;
  std::vector<Vec3> polygon, clipped;
  const auto& triangles = tissue.triangles();
  for (int f = 0; f < static_cast<int>(triangles.size()); ++f) {
    const std::array<int, 3>& t = triangles[static_cast<std::size_t>(f)];
    if (!skip.empty() && (skip[static_cast<std::size_t>(t[0])] || skip[static_cast<std::size_t>(t[1])] ||
                          skip[static_cast<std::size_t>(t[2])]))
      continue;
    if (tissue.isFixed(t[0]) && tissue.isFixed(t[1]) && tissue.isFixed(t[2])) continue;
    const Vec3 a = x.col(t[0]), b = x.col(t[1]), c = x.col(t[2]);
    if ((a.cwiseMax(b).cwiseMax(c).array() < region.boxLow.array()).any() ||
        (a.cwiseMin(b).cwiseMin(c).array() > region.boxHigh.array()).any())
      continue;

    // clip the face in barycentric coordinates: a plane's signed distance is b·(its corners')
    polygon = {Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()};
    for (const GraspPlane& h : region.planes) {
      const Vec3 corners(h.normal.dot(a) - h.offset, h.normal.dot(b) - h.offset, h.normal.dot(c) - h.offset);
      clipped.clear();
      for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Vec3& from = polygon[i];
        const Vec3& to = polygon[(i + 1) % polygon.size()];
        const double sf = from.dot(corners);
        const double st = to.dot(corners);
        if (sf <= 0.0) clipped.push_back(from);
        if ((sf <= 0.0) != (st <= 0.0)) clipped.push_back(from + sf / (sf - st) * (to - from));
      }
      polygon.swap(clipped);
      if (polygon.size() < 3) break;
    }
    if (polygon.size() < 3) continue;

    // the inside part's area and centroid, by a fan of triangles (the part is convex)
    const auto at = [&](const Vec3& w) { return Vec3(w.x() * a + w.y() * b + w.z() * c); };
    double area = 0.0;
    Vec3 centroid = Vec3::Zero();
    const Vec3 p0 = at(polygon[0]);
    for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
      const double part = 0.5 * (at(polygon[i]) - p0).cross(at(polygon[i + 1]) - p0).norm();
      area += part;
      centroid += part * (polygon[0] + polygon[i] + polygon[i + 1]) / 3.0;
    }
    const double faceArea = 0.5 * (b - a).cross(c - a).norm();
    if (!(area > kMinimumFaceShare * faceArea)) continue;
    out.push_back({f, centroid / area, area});
  }
  return out;
}

std::optional<ChainGrasp> chainPointBetweenJaws(const GraspRegion& region, const Points& x,
                                                const std::vector<std::uint8_t>& alive) {
  std::optional<ChainGrasp> best;
  for (int link = 0; link + 1 < static_cast<int>(x.cols()); ++link) {
    if (!alive.empty() && !alive[static_cast<std::size_t>(link)]) continue;
    const Vec3 a = x.col(link), b = x.col(link + 1);
    if ((a.cwiseMax(b).array() < region.boxLow.array()).any() ||
        (a.cwiseMin(b).array() > region.boxHigh.array()).any())
      continue;

    // the piece of the link inside every plane
    double t0 = 0.0, t1 = 1.0;
    for (const GraspPlane& h : region.planes) {
      const double sa = h.normal.dot(a) - h.offset;
      const double sb = h.normal.dot(b) - h.offset;
      if (sa > 0.0 && sb > 0.0) {
        t0 = 1.0;
        t1 = 0.0;
        break;
      }
      if (sa > 0.0) t0 = std::max(t0, sa / (sa - sb));
      if (sb > 0.0) t1 = std::min(t1, sa / (sa - sb));
    }
    if (t0 > t1) continue;

    // its point nearest the line where the jaws meet
    const collide::SegmentClosest q = collide::closestSegmentSegment(
        a + t0 * (b - a), a + t1 * (b - a), region.axisTip, region.axisHeel);
    if (!best || q.distance < best->distance) best = ChainGrasp{link, t0 + q.s * (t1 - t0), q.distance};
  }
  return best;
}

}  // namespace microsim::sim::tools
