#include "microsim/sim/suture/suture_contact.h"

#include "microsim/sim/collide/point_triangle.h"
#include "microsim/sim/collide/segment_segment.h"
#include "microsim/sim/collide/segment_triangle.h"

#include <algorithm>
#include <cmath>

namespace microsim::sim::suture {

namespace {

// cancels (static) or shortens (sliding) the tangential part of the node's motion since start
void applyFriction(Eigen::Ref<Vec3> x, const Vec3& start, const Vec3& normal, double pushed,
                   double friction) {
  const Vec3 motion = x - start;
  const Vec3 tangential = motion - motion.dot(normal) * normal;
  const double slip = tangential.norm();
  if (slip <= 0.0) return;
  const double hold = friction * pushed;
  x -= slip <= hold ? tangential : Vec3(tangential * (hold / slip));
}

}  // namespace

ContactSurface::ContactSurface(std::vector<std::array<int, 3>> triangles, const Points& x)
    : triangles_(std::move(triangles)), x_(x) {
  if (!triangles_.empty()) tree_ = collide::AabbTree::overTriangles(triangles_, x_);
}

void ContactSurface::update(const Points& x) {
  x_ = x;
  if (!triangles_.empty()) tree_.refitAll(x_);
}

bool ContactSurface::touching(int f, int g) const {
  for (int a : triangles_[f])
    for (int b : triangles_[g])
      if (a == b) return true;
  return false;
}

int projectCapsuleContacts(Points& x, const Points& xStart, std::span<const Capsule> capsules,
                           double radius, double friction, std::span<const std::uint8_t> movable,
                           std::vector<std::uint8_t>& touched) {
  int count = 0;
  for (Eigen::Index i = 0; i < x.cols(); ++i) {
    if (!movable[static_cast<std::size_t>(i)]) continue;
    for (const Capsule& c : capsules) {
      // closest point of the axis, push out along the radial direction
      const Vec3 p = x.col(i);
      const double t = collide::closestParameterOnSegment(p, c.a, c.b);
      const Vec3 axis = (1.0 - t) * c.a + t * c.b;
      const Vec3 off = p - axis;
      const double dist = off.norm();
      const double reach = c.radius + radius;
      if (dist >= reach) continue;
      Vec3 normal = dist > 0.0 ? Vec3(off / dist) : Vec3::UnitZ();
      if (dist == 0.0) {
        const Vec3 fromStart = xStart.col(i) - axis;
        if (fromStart.norm() > 0.0) normal = fromStart.normalized();
      }
      x.col(i) = axis + reach * normal;
      applyFriction(x.col(i), xStart.col(i), normal, reach - dist, friction);
      touched[static_cast<std::size_t>(i)] = 1;
      ++count;
    }
  }
  return count;
}

int projectSurfaceContacts(Points& x, const Points& xStart, const ContactSurface& surface,
                           double radius, double friction, std::span<const std::uint8_t> movable,
                           std::span<const ContactExemption> exemptions,
                           std::vector<std::uint8_t>& touched) {
  if (surface.empty()) return 0;
  const collide::AabbTree& tree = surface.tree();
  const Points& sx = surface.positions();
  const auto& tris = surface.triangles();
  std::vector<int> stack;
  std::vector<int> faces;
  int count = 0;
  for (Eigen::Index i = 0; i < x.cols(); ++i) {
    if (!movable[static_cast<std::size_t>(i)]) continue;

    // faces near the node's substep motion (a sphere around it)
    const Vec3 start = xStart.col(i);
    const Vec3 centre = 0.5 * (start + Vec3(x.col(i)));
    const double reach = 0.5 * (Vec3(x.col(i)) - start).norm() + radius;
    faces.clear();
    stack.assign(1, 0);
    while (!stack.empty()) {
      const int n = stack.back();
      stack.pop_back();
      if (!collide::near(tree.volume(n), centre, reach)) continue;
      const auto& node = tree.node(n);
      if (node.leaf()) {
        faces.push_back(node.feature);
      } else {
        stack.push_back(node.right);
        stack.push_back(node.left);
      }
    }
    std::sort(faces.begin(), faces.end());

    bool moved = false;
    Vec3 lastNormal = Vec3::Zero();
    double pushed = 0.0;
    for (int f : faces) {
      // skip faces the suture passes through at a pierce
      bool exempt = false;
      for (const ContactExemption& e : exemptions)
        if (i >= e.firstNode && i <= e.lastNode && surface.touching(f, e.face)) exempt = true;
      if (exempt) continue;

      const Vec3 a = sx.col(tris[f][0]);
      const Vec3 b = sx.col(tris[f][1]);
      const Vec3 c = sx.col(tris[f][2]);
      const Vec3 n = (b - a).cross(c - a);
      const double area2 = n.norm();
      if (area2 <= 0.0) continue;
      const Vec3 normal = n / area2;

      // crossed the face from its front during the substep: back to the front of the hit
      const Vec3 p = x.col(i);
      if ((start - a).dot(normal) >= 0.0 && (p - a).dot(normal) < 0.0) {
        if (auto hit = collide::intersectSegmentTriangle(start, p, a, b, c)) {
          x.col(i) = hit->point + radius * normal;
          pushed += radius;
          lastNormal = normal;
          moved = true;
          continue;
        }
      }

      // within the radius of the face, or behind it: out to the radius on the front
      const collide::PointTriangleClosest closest = collide::closestPointTriangle(p, a, b, c);
      const Vec3 off = p - closest.point;
      const double front = off.dot(normal);
      if (closest.distance >= radius && front >= 0.0) continue;
      if (front < 0.0 && closest.distance >= radius) continue;  // deep behind: another face's
      // behind the plane but beside the face (a convex edge): the neighbouring face decides
      if (front < 0.0 && closest.barycentric.minCoeff() <= 0.0) continue;
      const Vec3 dir = front > 0.0 && closest.distance > 0.0 ? Vec3(off / closest.distance) : normal;
      x.col(i) = closest.point + radius * dir;
      pushed += radius - (front > 0.0 ? closest.distance : -closest.distance);
      lastNormal = dir;
      moved = true;
    }
    if (!moved) continue;
    applyFriction(x.col(i), start, lastNormal, pushed, friction);
    touched[static_cast<std::size_t>(i)] = 1;
    ++count;
  }
  return count;
}

SelfContact::SelfContact(int linkCount) {
  segments_.resize(static_cast<std::size_t>(linkCount));
  for (int i = 0; i < linkCount; ++i) segments_[static_cast<std::size_t>(i)] = {i, i + 1};
}

int SelfContact::project(Points& x, const Points& xStart, double radius, double friction, int skip,
                         std::span<const std::uint8_t> movable,
                         const std::vector<std::uint8_t>& alive) {
  if (segments_.empty()) return 0;
  if (tree_.empty()) {
    tree_ = collide::AabbTree::overSegments(segments_, x);
  } else {
    tree_.refitAll(x);
  }
  const double gap = 2.0 * radius;
  collide::selfPairs(tree_, x, pairs_, gap);

  int count = 0;
  for (const collide::FeaturePair& pair : pairs_) {
    const int i = pair.first;
    const int j = pair.second;
    if (std::abs(j - i) < skip || !alive[static_cast<std::size_t>(i)] ||
        !alive[static_cast<std::size_t>(j)])
      continue;

    // closest points now; the separating direction from the substep's start
    const collide::SegmentClosest now =
        collide::closestSegmentSegment(x.col(i), x.col(i + 1), x.col(j), x.col(j + 1));
    if (now.distance >= gap) continue;
    const Vec3 p0 = (1.0 - now.s) * xStart.col(i) + now.s * xStart.col(i + 1);
    const Vec3 q0 = (1.0 - now.t) * xStart.col(j) + now.t * xStart.col(j + 1);
    Vec3 normal = q0 - p0;
    if (normal.norm() <= 0.0) normal = now.onSecond - now.onFirst;
    if (normal.norm() <= 0.0) continue;
    normal.normalize();
    const double along = (now.onSecond - now.onFirst).dot(normal);
    if (along >= gap) continue;

    // weights of the four nodes: barycentric share, zero for nodes that may not move
    const std::array<int, 4> node = {i, i + 1, j, j + 1};
    const std::array<double, 4> share = {-(1.0 - now.s), -now.s, 1.0 - now.t, now.t};
    double denom = 0.0;
    for (int k = 0; k < 4; ++k)
      if (movable[static_cast<std::size_t>(node[k])]) denom += share[k] * share[k];
    if (denom <= 0.0) continue;
    const double lambda = std::min(gap - along, 2.0 * gap) / denom;
    for (int k = 0; k < 4; ++k)
      if (movable[static_cast<std::size_t>(node[k])]) x.col(node[k]) += share[k] * lambda * normal;

    // friction on the relative tangential motion of the two contact points
    const Vec3 p1 = (1.0 - now.s) * x.col(i) + now.s * x.col(i + 1);
    const Vec3 q1 = (1.0 - now.t) * x.col(j) + now.t * x.col(j + 1);
    const Vec3 rel = (q1 - q0) - (p1 - p0);
    const Vec3 tangential = rel - rel.dot(normal) * normal;
    const double slip = tangential.norm();
    if (slip > 0.0) {
      const double hold = friction * (gap - along);
      const Vec3 cancel = slip <= hold ? tangential : Vec3(tangential * (hold / slip));
      for (int k = 0; k < 4; ++k)
        if (movable[static_cast<std::size_t>(node[k])])
          x.col(node[k]) -= share[k] / denom * cancel;
    }
    ++count;
  }
  return count;
}

}  // namespace microsim::sim::suture
