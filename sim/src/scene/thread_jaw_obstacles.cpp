#include "thread_jaw_obstacles.h"

#include "microsim/sim/collide/segment_segment.h"
#include "microsim/sim/tools/jaw_contact.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace microsim::sim {

namespace {

// mm: opened jaws this near the needle are not solid to the thread (header essay)
constexpr double kNeedleReach = 0.5;

// the radii of the two capsules a jaw becomes: its tip half, its heel half (mm)
std::array<double, 2> halfRadii(const tools::JawCapsule& jaw) {
  return {0.5 * (jaw.tipRadius + jaw.heelRadius), jaw.heelRadius};
}

// mm from p to the segment (a, b), and where along it (0..1)
std::pair<double, double> fromAxis(const Vec3& p, const Vec3& a, const Vec3& b) {
  const double t = collide::closestParameterOnSegment(p, a, b);
  return {(p - ((1.0 - t) * a + t * b)).norm(), t};
}

// the nodes of x between the jaws (header essay)
std::vector<Vec3> threadBetweenJaws(const tools::Forceps& forceps, const std::array<double, 2>& radii, const Points& x) {
  std::vector<Vec3> between;
  const ForcepsDef& def = forceps.def();
  // the space as it was before this frame's closure: jaws closing keep clear of what they
  // swept, and jaws opening do not count the turns their axes have just passed
  const double angle = tools::jawAngle(def, forceps.closedFrom());
  if (angle <= 0.0) return between;
  const double length = tools::jawLength(def);
  const double tanAngle = std::tan(angle);
  const double tipX = length - length * std::cos(angle);
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
  for (const Vec3& p : between) radius = std::min(radius, fromAxis(p, a, b).first - threadRadius);
  return {a, b, std::max(radius, 0.0)};
}

// true when a needle node (0..swage) lies within `reach` of a jaw's capsule
bool needleAtJaws(const std::array<tools::JawCapsule, 2>& jaws, const Points& x, int swage, double reach) {
  for (const tools::JawCapsule& jaw : jaws)
    for (int i = 0; i <= swage && i < x.cols(); ++i)
      if (fromAxis(x.col(i), jaw.tip, jaw.heel).first < jaw.heelRadius + reach) return true;
  return false;
}

// the held node and the chain on either side of it inside the jaws: first and last node
std::array<int, 2> heldRun(const tools::Forceps& forceps, const std::array<tools::JawCapsule, 2>& jaws,
                           const Points& x, double threadRadius) {
  const auto inside = [&](int i) {
    for (const tools::JawCapsule& c : jaws) {
      const auto [distance, t] = fromAxis(x.col(i), c.tip, c.heel);
      if (distance < c.tipRadius + t * (c.heelRadius - c.tipRadius) + threadRadius) return true;
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
  const std::array<tools::JawCapsule, 2> jaws = tools::jawCapsules(forceps);
  const std::array<double, 2> radii = halfRadii(jaws[0]);
  // what passes through: the held run while holding (capsules at full size), else nothing
  // (capsules thinned to leave the thread between opened jaws clear)
  std::array<int, 2> held{0, -1};
  std::vector<Vec3> between;
  if (forceps.holdsSuture()) {
    held = heldRun(forceps, jaws, x, threadRadius);
  } else {
    if (!forceps.closed() && needleAtJaws(jaws, x, swage, kNeedleReach)) return;
    between = threadBetweenJaws(forceps, radii, x);
  }
  for (const tools::JawCapsule& jaw : jaws) {
    const Vec3 middle = 0.5 * (jaw.tip + jaw.heel);
    for (suture::Capsule c : {clearOf(jaw.tip, middle, radii[0], between, threadRadius),
                              clearOf(middle, jaw.heel, radii[1], between, threadRadius)}) {
      c.freeFirst = held[0];
      c.freeLast = held[1];
      out.push_back(c);
    }
  }
}

}  // namespace microsim::sim
