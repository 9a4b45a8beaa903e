#include "thread_jaw_obstacles.h"

#include "microsim/sim/collide/segment_segment.h"
#include "microsim/sim/tools/jaw_contact.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace microsim::sim {

namespace {

// mm: opened jaws this near the needle are not solid to the thread (header essay)
constexpr double kNeedleReach = 0.5;

// the radii of the two capsules a jaw becomes: its tip half, its heel half (mm)
std::array<double, 2> halfRadii(const ForcepsDef& def) {
  const std::array<double, 2> radii = tools::jawRadii(def);
  return {0.5 * (radii[0] + radii[1]), radii[1]};
}

// the nodes of x between the jaws (header essay)
std::vector<Vec3> threadBetweenJaws(const tools::Forceps& forceps, const Points& x) {
  std::vector<Vec3> between;
  const ForcepsDef& def = forceps.def();
  // the space as it was before this frame's closure: jaws closing keep clear of what they
  // swept, and jaws opening do not count the turns their axes have just passed
  const double angle = tools::jawAngle(def, forceps.closedFrom());
  if (angle <= 0.0) return between;
  const double length = tools::jawLength(def);
  const double tanAngle = std::tan(angle);
  const double tipX = length - length * std::cos(angle);
  const std::array<double, 2> radii = halfRadii(def);
  const Eigen::Isometry3d toTool = forceps.pose().inverse();
  for (Eigen::Index i = 0; i < x.cols(); ++i) {
    const Vec3 q = toTool * Vec3(x.col(i));
    const double width = q.x() < 0.5 * length ? radii[0] : radii[1];
    if (q.x() <= length && q.x() >= tipX && std::abs(q.z()) < width && std::abs(q.y()) < (length - q.x()) * tanAngle)
      between.emplace_back(x.col(i));
  }
  return between;
}

// a capsule from a to b no thicker than leaves every node in `between` a thread's radius clear
suture::Capsule clearOf(const Vec3& a, const Vec3& b, double radius, const std::vector<Vec3>& between,
                        double threadRadius) {
  for (const Vec3& p : between) {
    const double t = collide::closestParameterOnSegment(p, a, b);
    radius = std::min(radius, (p - ((1.0 - t) * a + t * b)).norm() - threadRadius);
  }
  return {a, b, std::max(radius, 0.0)};
}

// true when a needle node (0..swage) lies within `reach` of a jaw's capsule
bool needleAtJaws(const tools::Forceps& forceps, const Points& x, int swage, double reach) {
  const std::array<double, 2> radii = halfRadii(forceps.def());
  for (const tools::JawCapsule& jaw : tools::jawCapsules(forceps)) {
    for (int i = 0; i <= swage && i < x.cols(); ++i) {
      const double t = collide::closestParameterOnSegment(x.col(i), jaw.tip, jaw.heel);
      if ((x.col(i) - ((1.0 - t) * jaw.tip + t * jaw.heel)).norm() < std::max(radii[0], radii[1]) + reach) return true;
    }
  }
  return false;
}


// the held node and the chain on either side of it inside the jaws: first and last node
std::array<int, 2> heldRun(const tools::Forceps& forceps, const Points& x, double threadRadius) {
  const std::array<tools::JawCapsule, 2> jaws = tools::jawCapsules(forceps);
  const auto inside = [&](int i) {
    for (const tools::JawCapsule& c : jaws) {
      const double t = collide::closestParameterOnSegment(x.col(i), c.tip, c.heel);
      const double radius = c.tipRadius + t * (c.heelRadius - c.tipRadius) + threadRadius;
      if ((x.col(i) - ((1.0 - t) * c.tip + t * c.heel)).norm() < radius) return true;
    }
    return false;
  };
  const int last = static_cast<int>(x.cols()) - 1;
  int first = forceps.heldSutureNode();
  int end = std::min(forceps.heldSutureFraction() > 0.0 ? first + 1 : first, last);
  while (first > 0 && inside(first - 1)) --first;
  while (end < last && inside(end + 1)) ++end;
  return {first, end};
}

}  // namespace

void appendThreadJawObstacles(const tools::Forceps& forceps, const Points& x, int swage, double threadRadius,
                              std::vector<suture::Capsule>& out) {
  const std::array<double, 2> radii = halfRadii(forceps.def());
  if (forceps.holdsSuture()) {
    const std::array<int, 2> held = heldRun(forceps, x, threadRadius);
    for (const tools::JawCapsule& jaw : tools::jawCapsules(forceps)) {
      const Vec3 middle = 0.5 * (jaw.tip + jaw.heel);
      out.push_back({jaw.tip, middle, radii[0], held[0], held[1]});
      out.push_back({middle, jaw.heel, radii[1], held[0], held[1]});
    }
    return;
  }
  if (!forceps.closed() && needleAtJaws(forceps, x, swage, kNeedleReach)) return;
  const std::vector<Vec3> between = threadBetweenJaws(forceps, x);
  for (const tools::JawCapsule& jaw : tools::jawCapsules(forceps)) {
    const Vec3 middle = 0.5 * (jaw.tip + jaw.heel);
    out.push_back(clearOf(jaw.tip, middle, radii[0], between, threadRadius));
    out.push_back(clearOf(middle, jaw.heel, radii[1], between, threadRadius));
  }
}

}  // namespace microsim::sim
