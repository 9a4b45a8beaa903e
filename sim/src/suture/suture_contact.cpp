#include "microsim/sim/suture/suture_contact.h"

#include "microsim/sim/collide/point_triangle.h"
#include "microsim/sim/collide/segment_segment.h"
#include "microsim/sim/collide/segment_triangle.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

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

// The denominator of a push on a contact point Σ share_k x_k of the movable nodes (movable_k
// = 1): Σ share_k² moves the point by exactly the depth, but when the point lies next to a
// node that cannot move (a pierce's, a grip's) the movable share is small and the lever sends
// its node depth / share away — a node beside a pierce was flung 0.9 mm in one pass and the
// link from it stretched 22-fold. With the largest movable share as a floor no node moves
// farther than the depth itself (nor, for friction, than the slip); what is left of the
// overlap is taken by the next pass, as the lengths are. 0: nothing may move.
double leverDenominator(std::span<const double> share, std::span<const double> movable) {
  double sum = 0.0;
  double largest = 0.0;
  for (std::size_t k = 0; k < share.size(); ++k) {
    sum += movable[k] * share[k] * share[k];
    largest = std::max(largest, movable[k] * std::abs(share[k]));
  }
  return largest > 0.0 ? std::max(sum, largest) : 0.0;
}

// Whether `normal` runs along both links i and j (within 25°): two links lying on one line,
// as a thread pushed shorter along a straight line folds. No push along the line parts them
// (it only stretches the links, 20-33 % for as long as the fold lasts), and no side is the
// right one to push them to.
bool alongBoth(const Points& x, int i, int j, const Vec3& normal) {
  constexpr double kAlong = 0.9;
  const Vec3 a = x.col(i + 1) - x.col(i);
  const Vec3 b = x.col(j + 1) - x.col(j);
  return std::abs(normal.dot(a)) > kAlong * a.norm() && std::abs(normal.dot(b)) > kAlong * b.norm();
}

}  // namespace

void ChainBlocks::update(const Points& x, const Points* xStart, double margin) {
  const int nodes = static_cast<int>(x.cols());
  const int count = nodes > 1 ? (nodes - 2) / kNodes + 1 : (nodes > 0 ? 1 : 0);
  boxes.resize(static_cast<std::size_t>(count));
  for (int b = 0; b < count; ++b) {
    const int first = b * kNodes;
    const int last = std::min(first + kNodes, nodes - 1);
    Vec3 lo = x.col(first);
    Vec3 hi = lo;
    for (int i = first; i <= last; ++i) {
      lo = lo.cwiseMin(x.col(i));
      hi = hi.cwiseMax(x.col(i));
      if (xStart) {
        lo = lo.cwiseMin(xStart->col(i));
        hi = hi.cwiseMax(xStart->col(i));
      }
    }
    boxes[static_cast<std::size_t>(b)] = {lo.array() - margin, hi.array() + margin};
  }
}

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

namespace {

bool boxesOverlap(const collide::Aabb& p, const collide::Aabb& q) {
  return (p.lo.array() <= q.hi.array()).all() && (q.lo.array() <= p.hi.array()).all();
}

}  // namespace

namespace {

// pushes link (i, i + 1) out of capsule c where its interior passes closer than `reach` to the
// axis (the nodes' own tests cover the ends); the side is the one the link came from
bool pushLinkOutOfCapsule(Points& x, const Points& xStart, Eigen::Index i, const Capsule& c,
                          double reach, double friction, std::span<const std::uint8_t> movable) {
  const std::size_t i0 = static_cast<std::size_t>(i);
  const std::array<double, 2> m = {movable[i0] ? 1.0 : 0.0, movable[i0 + 1] ? 1.0 : 0.0};
  if (m[0] + m[1] == 0.0) return false;
  const collide::SegmentClosest now = collide::closestSegmentSegment(x.col(i), x.col(i + 1), c.a, c.b);
  if (now.distance >= reach || now.s <= 0.0 || now.s >= 1.0) return false;
  const Vec3 startPoint = (1.0 - now.s) * xStart.col(i) + now.s * xStart.col(i + 1);
  const Vec3 fromStart = startPoint - ((1.0 - now.t) * c.a + now.t * c.b);
  Vec3 normal = now.onFirst - now.onSecond;
  // crossed the axis within the substep (or on it): back to the side it came from
  if (fromStart.squaredNorm() > 0.0 && (normal.dot(fromStart) <= 0.0 || now.distance == 0.0))
    normal = fromStart;
  if (!(normal.norm() > 0.0)) return false;
  normal.normalize();
  const double depth = reach - (now.onFirst - now.onSecond).dot(normal);
  const std::array<double, 2> share = {1.0 - now.s, now.s};
  const double denom = leverDenominator(share, m);
  if (!(denom > 0.0)) return false;
  const double lambda = depth / denom;
  for (int k = 0; k < 2; ++k) x.col(i + k) += m[k] * share[k] * lambda * normal;

  // friction on the contact point's tangential motion since the substep's start
  const Vec3 motion = (1.0 - now.s) * x.col(i) + now.s * x.col(i + 1) - startPoint;
  const Vec3 tangential = motion - motion.dot(normal) * normal;
  const double slip = tangential.norm();
  if (slip > 0.0) {
    const double hold = friction * depth;
    const Vec3 cancel = slip <= hold ? tangential : Vec3(tangential * (hold / slip));
    for (int k = 0; k < 2; ++k) x.col(i + k) -= m[k] * share[k] / denom * cancel;
  }
  return true;
}

}  // namespace

int projectCapsuleContacts(Points& x, const Points& xStart, std::span<const Capsule> capsules,
                           double radius, double friction, std::span<const std::uint8_t> movable,
                           std::vector<std::uint8_t>& touched, ChainBlocks* scratch,
                           std::span<const std::uint8_t> alive) {
  if (capsules.empty()) return 0;
  ChainBlocks local;
  ChainBlocks& blocks = scratch ? *scratch : local;
  blocks.update(x, &xStart, radius);
  int count = 0;
  const Eigen::Index nodes = x.cols();
  for (int b = 0; b < blocks.count(); ++b) {
    // the capsules this block's swept box reaches
    std::uint32_t reached = 0;
    for (std::size_t k = 0; k < capsules.size() && k < 32; ++k) {
      const Capsule& c = capsules[k];
      const collide::Aabb box{c.a.cwiseMin(c.b).array() - c.radius, c.a.cwiseMax(c.b).array() + c.radius};
      if (boxesOverlap(box, blocks.boxes[static_cast<std::size_t>(b)])) reached |= 1u << k;
    }
    if (capsules.size() > 32) reached = ~0u;
    if (reached == 0) continue;
    const Eigen::Index first = ChainBlocks::firstNode(b);
    const Eigen::Index end = std::min<Eigen::Index>(first + ChainBlocks::kNodes, nodes);
    for (std::size_t k = 0; k < capsules.size(); ++k) {
      if (k < 32 && !(reached & (1u << k))) continue;
      const Capsule& c = capsules[k];
      const double reach = c.radius + radius;
      for (Eigen::Index i = first; i < end; ++i) {
        // the thread the jaws hold, and the links from it, pass
        const bool freeNode = i >= c.freeFirst && i <= c.freeLast;
        const bool freeLink = i + 1 >= c.freeFirst && i <= c.freeLast;
        // the node: closest point of the axis, push out along the radial direction
        if (movable[static_cast<std::size_t>(i)] && !freeNode) {
          const Vec3 p = x.col(i);
          const double t = collide::closestParameterOnSegment(p, c.a, c.b);
          const Vec3 axis = (1.0 - t) * c.a + t * c.b;
          const Vec3 off = p - axis;
          const double dist = off.norm();
          if (dist < reach) {
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
        // the link to the next node: a link as long as the jaw is thick may straddle it with
        // both nodes outside, and its nodes pushed to opposite sides could never meet again
        if (i + 1 < nodes && !freeLink && (alive.empty() || alive[static_cast<std::size_t>(i)]) &&
            pushLinkOutOfCapsule(x, xStart, i, c, reach, friction, movable)) {
          touched[static_cast<std::size_t>(i)] = 1;
          touched[static_cast<std::size_t>(i + 1)] = 1;
          ++count;
        }
      }
    }
  }
  return count;
}

HullOffset hullOffset(const Sleeve& sleeve, const Vec3& p, const Vec3& side) {
  // the slab between the jaws: within the triangle its axes span, out along the plane's normal
  // on the node's side (on the plane itself: the side it came from); beyond it, as capsules do
  const collide::PointTriangleClosest slab =
      collide::closestPointTriangle(p, sleeve.hinge, sleeve.tipA, sleeve.tipB);
  const Vec3 plane = (sleeve.tipA - sleeve.hinge).cross(sleeve.tipB - sleeve.hinge);
  const bool within = plane.norm() > 0.0 && (slab.barycentric.array() > 0.0).all();
  HullOffset out;
  out.distance = slab.distance - sleeve.slabRadius;
  if (within) {
    const Vec3 n = plane.normalized();
    const double height = (p - slab.point).dot(n);
    const double from = height != 0.0 ? height : (side - slab.point).dot(n);
    out.normal = from < 0.0 ? Vec3(-n) : n;
  } else if (slab.distance > 0.0) {
    out.normal = (p - slab.point) / slab.distance;
  }
  // the jaws' capsules: the nearest surface wins
  for (const Capsule& c : sleeve.jaws) {
    const double t = collide::closestParameterOnSegment(p, c.a, c.b);
    const Vec3 off = p - ((1.0 - t) * c.a + t * c.b);
    const double d = off.norm() - c.radius;
    if (d < out.distance && off.norm() > 0.0) {
      out.distance = d;
      out.normal = off.normalized();
    }
  }
  return out;
}

int projectSleeves(Points& x, const Points& xStart, std::span<const Sleeve> sleeves, double radius,
                   double friction, std::span<const std::uint8_t> movable,
                   std::vector<std::uint8_t>& touched) {
  int count = 0;
  for (const Sleeve& s : sleeves) {
    for (int i = std::max(s.first, 0); i <= s.last && i < x.cols(); ++i) {
      if (!movable[static_cast<std::size_t>(i)]) continue;
      const HullOffset at = hullOffset(s, x.col(i), xStart.col(i));
      // a thread's radius off the hull, and no more than the slack beyond that
      const double move = at.distance < radius             ? radius - at.distance
                          : at.distance > radius + s.slack ? radius + s.slack - at.distance
                                                           : 0.0;
      if (move == 0.0) continue;
      x.col(i) += move * at.normal;
      applyFriction(x.col(i), xStart.col(i), at.normal, std::abs(move), friction);
      touched[static_cast<std::size_t>(i)] = 1;
      ++count;
    }
  }
  return count;
}

int projectSurfaceContacts(Points& x, const Points& xStart, const ContactSurface& surface,
                           double radius, double friction, std::span<const std::uint8_t> movable,
                           std::span<const ContactExemption> exemptions,
                           std::vector<std::uint8_t>& touched, ChainBlocks* scratch) {
  if (surface.empty()) return 0;
  const collide::AabbTree& tree = surface.tree();
  const Points& sx = surface.positions();
  const auto& tris = surface.triangles();
  ChainBlocks local;
  ChainBlocks& blocks = scratch ? *scratch : local;
  blocks.update(x, &xStart, radius);
  std::vector<int> stack;
  std::vector<int> faces;
  int count = 0;
  for (Eigen::Index i = 0; i < x.cols(); ++i) {
    if (!movable[static_cast<std::size_t>(i)]) continue;
    // blocks whose swept box misses the surface's root box
    // block b spans nodes 16b..16b+16, so the last node can belong only to the block before
    const std::size_t block = std::min(static_cast<std::size_t>(i / ChainBlocks::kNodes), blocks.boxes.size() - 1);
    if (!boxesOverlap(blocks.boxes[block], tree.volume(0))) {
      i = std::max(i, std::min<Eigen::Index>(x.cols(), static_cast<Eigen::Index>(block + 1) * ChainBlocks::kNodes) - 1);
      continue;
    }

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

SelfContact::SelfContact(int linkCount) : links_(linkCount) {}

bool SelfContact::straight(const Points& x, int firstLink, int endLink, double gap, int skip) const {
  const Vec3 chord = x.col(endLink) - x.col(firstLink);
  const double length = chord.norm();
  if (!(length > 0.0)) return false;
  const Vec3 d = chord / length;
  double least = std::numeric_limits<double>::infinity();
  for (int k = firstLink; k < endLink; ++k) least = std::min(least, (x.col(k + 1) - x.col(k)).dot(d));
  return least > 0.0 && (skip - 1) * least >= gap;
}

void SelfContact::collect(const Points& x, const Points& xStart, double radius, int skip,
                          const std::vector<std::uint8_t>& alive) {
  pairs_.clear();
  const double gap = 2.0 * radius;
  // an unbroken straight chain touches nothing (separate pieces may touch each other)
  if (std::find(alive.begin(), alive.end(), std::uint8_t{0}) == alive.end()) {
    bool all = true;
    int first = 0;
    for (int l = 0; l <= links_ && all; ++l) {
      if (l < links_ && alive[static_cast<std::size_t>(l)]) continue;
      if (l - first >= skip &&
          !(straight(x, first, l, gap, skip) && straight(xStart, first, l, gap, skip)))
        all = false;
      first = l + 1;
    }
    if (all) return;
  }

  // boxes: per block of links and per link, grown by the radius
  const int nodes = links_ + 1;
  blocks_.update(x, &xStart, radius);
  const int blockCount = blocks_.count();
  linkBoxes_.resize(static_cast<std::size_t>(links_));
  linkSpheres_.resize(static_cast<std::size_t>(links_));
  for (int l = 0; l < links_; ++l) {
    const Vec3 lo = x.col(l).cwiseMin(x.col(l + 1)).cwiseMin(xStart.col(l)).cwiseMin(xStart.col(l + 1));
    const Vec3 hi = x.col(l).cwiseMax(x.col(l + 1)).cwiseMax(xStart.col(l)).cwiseMax(xStart.col(l + 1));
    linkBoxes_[static_cast<std::size_t>(l)] = {lo.array() - radius, hi.array() + radius};
    // every point of the link over the substep (nodes moving linearly from xStart) lies within
    // half its length plus its nodes' larger motion of its midpoint now
    const double moved = std::sqrt(std::max((x.col(l) - xStart.col(l)).squaredNorm(),
                                            (x.col(l + 1) - xStart.col(l + 1)).squaredNorm()));
    Sphere& sphere = linkSpheres_[static_cast<std::size_t>(l)];
    sphere.centre = 0.5 * (x.col(l) + x.col(l + 1));
    sphere.radius = 0.5 * (x.col(l + 1) - x.col(l)).norm() + moved + radius;
  }
  const auto touches = [](const Sphere& p, const Sphere& q) {
    const double reach = p.radius + q.radius;
    return (p.centre - q.centre).squaredNorm() < reach * reach;
  };
  const auto overlap = [](const collide::Aabb& p, const collide::Aabb& q) {
    return (p.lo.array() <= q.hi.array()).all() && (q.lo.array() <= p.hi.array()).all();
  };
  const auto linkRange = [&](int block) {
    const int first = ChainBlocks::firstNode(block);
    return std::array<int, 2>{first, std::min(first + ChainBlocks::kNodes, nodes - 1)};
  };
  // a run [first, end) of intact links that is straight
  const auto straightRun = [&](int first, int end) {
    for (int l = first; l < end; ++l)
      if (!alive[static_cast<std::size_t>(l)]) return false;
    return straight(x, first, end, gap, skip) && straight(xStart, first, end, gap, skip);
  };
  const auto testLinks = [&](int i0, int i1, int j0, int j1) {
    for (int i = i0; i < i1; ++i)
      for (int j = std::max(j0, i + skip); j < j1; ++j)
        if (overlap(linkBoxes_[static_cast<std::size_t>(i)], linkBoxes_[static_cast<std::size_t>(j)]) &&
            touches(linkSpheres_[static_cast<std::size_t>(i)], linkSpheres_[static_cast<std::size_t>(j)]))
          pairs_.push_back({i, j});
  };

  // block against itself, then against every later block
  for (int b = 0; b < blockCount; ++b) {
    const auto [b0, b1] = linkRange(b);
    if (b1 <= b0) continue;
    if (!straightRun(b0, b1)) testLinks(b0, b1, b0, b1);
    for (int c = b + 1; c < blockCount; ++c) {
      const auto [c0, c1] = linkRange(c);
      if (c1 <= c0 || !overlap(blocks_.boxes[static_cast<std::size_t>(b)],
                               blocks_.boxes[static_cast<std::size_t>(c)]))
        continue;
      if (c == b + 1 && straightRun(b0, c1)) continue;
      testLinks(b0, b1, c0, c1);
    }
  }
}

int SelfContact::project(Points& x, const Points& xStart, double radius, double friction, int skip,
                         std::span<const std::uint8_t> movable,
                         const std::vector<std::uint8_t>& alive,
                         std::vector<std::uint8_t>* touched) {
  if (links_ == 0) return 0;
  const double gap = 2.0 * radius;
  collect(x, xStart, radius, skip, alive);

  int count = 0;
  for (const auto& [i, j] : pairs_) {
    if (!alive[static_cast<std::size_t>(i)] || !alive[static_cast<std::size_t>(j)]) continue;

    // closest points now, the separating direction from the substep's start; a pair apart
    // now but closer than the gap at its closest points of the start, carried to now, passed
    // through itself within the substep (continuous check)
    collide::SegmentClosest c =
        collide::closestSegmentSegment(x.col(i), x.col(i + 1), x.col(j), x.col(j + 1));
    Vec3 normal;
    double cap = 2.0 * gap;
    if (c.distance < gap) {
      normal = ((1.0 - c.t) * xStart.col(j) + c.t * xStart.col(j + 1)) -
               ((1.0 - c.s) * xStart.col(i) + c.s * xStart.col(i + 1));
      if (normal.norm() <= 0.0) normal = c.onSecond - c.onFirst;
    } else {
      c = collide::closestSegmentSegment(xStart.col(i), xStart.col(i + 1), xStart.col(j),
                                         xStart.col(j + 1));
      normal = c.onSecond - c.onFirst;
      cap = std::numeric_limits<double>::infinity();
    }
    if (normal.norm() <= 0.0) continue;
    normal.normalize();
    if (alongBoth(x, i, j, normal)) continue;
    const Vec3 p0 = (1.0 - c.s) * xStart.col(i) + c.s * xStart.col(i + 1);
    const Vec3 q0 = (1.0 - c.t) * xStart.col(j) + c.t * xStart.col(j + 1);
    const double along = (((1.0 - c.t) * x.col(j) + c.t * x.col(j + 1)) -
                          ((1.0 - c.s) * x.col(i) + c.s * x.col(i + 1))).dot(normal);
    if (along >= gap) continue;

    // weights of the four nodes: barycentric share, zero for nodes that may not move
    const std::array<int, 4> node = {i, i + 1, j, j + 1};
    const std::array<double, 4> share = {-(1.0 - c.s), -c.s, 1.0 - c.t, c.t};
    std::array<double, 4> m{};
    for (std::size_t k = 0; k < 4; ++k) m[k] = movable[static_cast<std::size_t>(node[k])] ? 1.0 : 0.0;
    const double denom = leverDenominator(share, m);
    if (denom <= 0.0) continue;
    const double lambda = std::min(gap - along, cap) / denom;
    for (int k = 0; k < 4; ++k)
      if (movable[static_cast<std::size_t>(node[k])]) x.col(node[k]) += share[k] * lambda * normal;

    // friction on the relative tangential motion of the two contact points
    const Vec3 p1 = (1.0 - c.s) * x.col(i) + c.s * x.col(i + 1);
    const Vec3 q1 = (1.0 - c.t) * x.col(j) + c.t * x.col(j + 1);
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
    if (touched)
      for (int n : node) (*touched)[static_cast<std::size_t>(n)] = 1;
    ++count;
  }
  return count;
}

}  // namespace microsim::sim::suture
