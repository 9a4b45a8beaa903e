#include "microsim/sim/tools/needle.h"

#include "microsim/sim/collide/segment_triangle.h"
#include "microsim/sim/suture/suture_constraints.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace microsim::sim::tools {

Vec3 faceNormal(const SpringModel& tissue, const Points& x, int face) {
  const auto& t = tissue.triangles()[static_cast<std::size_t>(face)];
  const Vec3 n = (x.col(t[1]) - x.col(t[0])).cross(x.col(t[2]) - x.col(t[0]));
  const double len = n.norm();
  return len > 0.0 ? Vec3(n / len) : Vec3::Zero();
}

Vec3 needleTipTangent(const suture::SutureModel& model, const suture::Points& x) {
  if (model.needleLinks() == 0 || model.def().needleShape == suture::NeedleShape::Straight) {
    const Vec3 d = x.col(0) - x.col(1);
    return d.normalized();
  }
  // the rest shape's tangent at node 0 points from the swage side towards the tip: −x
  const Eigen::Matrix3d r = suture::needleRotation(model, x);
  return (r * Vec3(-1.0, 0.0, 0.0)).normalized();
}

Vec3 needleTangentNear(const suture::SutureModel& model, const suture::Points& x, const Vec3& p) {
  if (model.needleLinks() == 0 || model.def().needleShape == suture::NeedleShape::Straight)
    return needleTipTangent(model, x);
  // the rest shape is (R sin θ, R (1 − cos θ), 0) from the tip (θ = 0) to the swage (θ = 3π/4)
  const double radius = model.def().needleRadius;
  const Eigen::Matrix3d r = suture::needleRotation(model, x);
  const Vec3 centre = x.col(0) + r * Vec3(0.0, radius, 0.0);
  const Vec3 local = r.transpose() * (p - centre);
  // θ of p's direction from the centre, seen in the needle's plane, clamped to the arc
  const double theta = std::clamp(std::atan2(local.x(), -local.y()), 0.0, 0.75 * std::numbers::pi);
  return (r * Vec3(-std::cos(theta), -std::sin(theta), 0.0)).normalized();
}

double pierceAngleDeg(const Vec3& tangent, const Vec3& normal) {
  const double c = std::min(1.0, std::abs(tangent.normalized().dot(normal.normalized())));
  return std::acos(c) * 180.0 / std::numbers::pi;
}

template <class Volume>
PierceDetector<Volume>::PierceDetector(const SpringModel& tissue, const Points& x)
    : tree_(collide::BvhTree<Volume>::overTriangles(tissue.triangles(), x)) {
  pathX_.setZero();
  const std::array<std::array<int, 2>, 1> segment{{{0, 1}}};
  path_ = collide::BvhTree<Volume>::overSegments(segment, pathX_);
}

template <class Volume>
void PierceDetector<Volume>::maintain(const std::vector<int>& moved, const Points& x) {
  if (!moved.empty()) tree_.maintainVertices(moved, x);
}

template <class Volume>
void PierceDetector<Volume>::crossings(const SpringModel& tissue, const Points& x, const Vec3& p,
                                       const Vec3& q, std::vector<FaceCrossing>& out) {
  out.clear();
  if (tree_.empty() || p == q) return;
  pathX_.col(0) = p;
  pathX_.col(1) = q;
  path_.refitAll(pathX_);
  collide::allPairs(path_, pathX_, tree_, x, pairs_);

  // exact crossings, then path order
  for (const collide::FeaturePair& pair : pairs_) {
    const auto& t = tissue.triangles()[static_cast<std::size_t>(pair.second)];
    const auto hit = collide::intersectSegmentTriangle(p, q, x.col(t[0]), x.col(t[1]), x.col(t[2]));
    if (!hit) continue;
    FaceCrossing c;
    c.face = pair.second;
    c.t = hit->t;
    c.point = hit->point;
    c.barycentric = hit->barycentric;
    c.normal = faceNormal(tissue, x, pair.second);
    const double along = (q - p).dot(c.normal);
    if (along == 0.0) continue;  // sliding within the face's plane crosses nothing
    c.entry = along < 0.0;
    out.push_back(c);
  }
  std::sort(out.begin(), out.end(), [](const FaceCrossing& a, const FaceCrossing& b) {
    return a.t != b.t ? a.t < b.t : a.face < b.face;
  });

  // one crossing through an edge or corner shared by faces of one surface
  const double merge = 1e-9;
  std::vector<FaceCrossing> unique;
  for (const FaceCrossing& c : out) {
    const bool duplicate = !unique.empty() && unique.back().entry == c.entry &&
                           std::abs(unique.back().t - c.t) * (q - p).norm() <= merge &&
                           unique.back().normal.dot(c.normal) > 0.0;
    if (!duplicate) unique.push_back(c);
  }
  out.swap(unique);
}

template <class Volume>
void PierceDetector<Volume>::passedOver(const SpringModel& tissue, const Points& before, const Points& x,
                                        const Vec3& tip, double reach, std::vector<FaceCrossing>& out) {
  out.clear();
  if (tree_.empty() || !(reach > 0.0)) return;
  Points at(3, 1);
  at.col(0) = tip;
  collide::pointsNear(tree_, x, at, reach, near_);
  for (const collide::PointNearFeature& f : near_) {
    const auto& t = tissue.triangles()[static_cast<std::size_t>(f.feature)];
    const Vec3 n0 = faceNormal(tissue, before, f.feature);
    const Vec3 n1 = faceNormal(tissue, x, f.feature);
    const double s0 = (tip - before.col(t[0])).dot(n0);
    const double s1 = (tip - x.col(t[0])).dot(n1);
    if (!((s0 > 0.0 && s1 <= 0.0) || (s0 < 0.0 && s1 >= 0.0))) continue;

    // the face where it met the tip, and the tip's place on it
    const double lambda = s0 / (s0 - s1);
    std::array<Vec3, 3> corner;
    for (std::size_t c = 0; c < 3; ++c) corner[c] = before.col(t[c]) + lambda * (x.col(t[c]) - before.col(t[c]));
    const Vec3 e1 = corner[1] - corner[0];
    const Vec3 e2 = corner[2] - corner[0];
    const Vec3 r = tip - corner[0];
    const double d11 = e1.dot(e1), d12 = e1.dot(e2), d22 = e2.dot(e2);
    const double det = d11 * d22 - d12 * d12;
    if (!(det > 0.0)) continue;
    const double v = (d22 * r.dot(e1) - d12 * r.dot(e2)) / det;
    const double w = (d11 * r.dot(e2) - d12 * r.dot(e1)) / det;
    if (v < 0.0 || w < 0.0 || v + w > 1.0) continue;
    FaceCrossing c;
    c.face = f.feature;
    c.t = 1.0;
    c.barycentric = Vec3(1.0 - v - w, v, w);
    c.point = c.barycentric.x() * x.col(t[0]) + c.barycentric.y() * x.col(t[1]) + c.barycentric.z() * x.col(t[2]);
    c.normal = n1;
    c.entry = s0 > 0.0;
    out.push_back(c);
  }
  std::sort(out.begin(), out.end(), [](const FaceCrossing& a, const FaceCrossing& b) { return a.face < b.face; });

  // one crossing where the tip met an edge or corner shared by faces of one surface
  std::vector<FaceCrossing> unique;
  for (const FaceCrossing& c : out)
    if (std::none_of(unique.begin(), unique.end(), [&](const FaceCrossing& u) {
          return u.entry == c.entry && (u.point - c.point).norm() <= 1e-9 && u.normal.dot(c.normal) > 0.0;
        }))
      unique.push_back(c);
  out.swap(unique);
}

template class PierceDetector<collide::Sphere>;
template class PierceDetector<collide::Aabb>;

}  // namespace microsim::sim::tools
