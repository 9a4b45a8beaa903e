#include "thread_jaw_obstacles.h"

#include "microsim/sim/collide/point_triangle.h"
#include "microsim/sim/collide/segment_segment.h"
#include "microsim/sim/tools/jaw_contact.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace microsim::sim {

namespace {

// mm: opened jaws this near the needle are not solid to the thread (header essay)
constexpr double kNeedleReach = 0.5;
// turns: the least winding of a wound run; how far off the jaws' hull a node may lie to count,
// and to be kept (mm; the second below the first, so turns the sleeve keeps stay wound)
constexpr int kWoundQuarterTurns = 4;
constexpr double kCaptureMargin = 0.06;
// mm: how deep into the jaws' hull a wound node may have been pressed (the last length restore
// of a substep lets a turn pulled tight sink a few µm; the jaws open a little every frame);
// thread between the jaws lies deeper, a jaw's radius in
constexpr double kPressedDepth = 0.03;
constexpr double kSleeveSlack = 0.03;

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

// the two capsules a jaw becomes (header essay)
std::array<suture::Capsule, 2> jawHalves(const tools::JawCapsule& jaw) {
  const std::array<double, 2> radii = halfRadii(jaw);
  const Vec3 middle = 0.5 * (jaw.tip + jaw.heel);
  return {suture::Capsule{jaw.tip, middle, radii[0]}, suture::Capsule{middle, jaw.heel, radii[1]}};
}

// the held node and the chain on either side of it inside the jaws: first and last node. A
// node inside the tapered jaw is inside; so is one nearer the held point than the rim of the
// capsule the thread meets there (jawHalves, thicker than the jaw near its tip). Before, a
// node 0.1 mm from a grip at the tip lay outside the jaw but inside the capsule, was pushed out
// to its rim on every other step while the held node stayed, and the links beside the grip
// stood 58 % over length, which read as a knot pulled tight. Turns wound round the jaws lie
// farther from the held point than that, and stay solid to them.
std::array<int, 2> heldRun(const tools::Forceps& forceps, const std::array<tools::JawCapsule, 2>& jaws,
                           const Points& x, double threadRadius) {
  const int last = static_cast<int>(x.cols()) - 1;
  int first = forceps.heldSutureNode();
  const double fraction = forceps.heldSutureFraction();
  int end = std::min(fraction > 0.0 ? first + 1 : first, last);
  const Vec3 held = (1.0 - fraction) * x.col(first) + fraction * x.col(end);
  double reach = 0.0;  // the rim of the capsule nearest the held point
  double nearest = std::numeric_limits<double>::infinity();
  for (const tools::JawCapsule& jaw : jaws)
    for (const suture::Capsule& c : jawHalves(jaw)) {
      const double d = fromAxis(held, c.a, c.b).first - c.radius;
      if (d < nearest) {
        nearest = d;
        reach = c.radius + threadRadius;
      }
    }
  const auto inside = [&](int i) {
    if ((x.col(i) - held).norm() < reach) return true;
    for (const tools::JawCapsule& c : jaws) {
      const auto [distance, t] = fromAxis(x.col(i), c.tip, c.heel);
      if (distance < c.tipRadius + t * (c.heelRadius - c.tipRadius) + threadRadius) return true;
    }
    return false;
  };
  while (first > 0 && inside(first - 1)) --first;
  while (end < last && inside(end + 1)) ++end;
  return {first, end};
}

// the hull of the two jaws: their capsules and the slab between them (suture_contact.h)
suture::Sleeve jawHull(const std::array<tools::JawCapsule, 2>& jaws) {
  suture::Sleeve hull;
  for (std::size_t j = 0; j < 2; ++j) {
    const std::array<suture::Capsule, 2> halves = jawHalves(jaws[j]);
    hull.jaws[2 * j] = halves[0];
    hull.jaws[2 * j + 1] = halves[1];
  }
  hull.hinge = jaws[0].heel;
  hull.tipA = jaws[0].tip;
  hull.tipB = jaws[1].tip;
  hull.slabRadius = halfRadii(jaws[0])[0];
  hull.slack = kSleeveSlack;
  return hull;
}

// the quadrant of (y, z) about the tool's axis: 0 to 3 counterclockwise from +y
int quadrant(const Vec3& q) {
  if (q.z() >= 0.0) return q.y() >= 0.0 ? 0 : 1;
  return q.y() < 0.0 ? 2 : 3;
}

// the quadrants from a to b about the tool's axis, signed (counterclockwise positive; 2: to
// the opposite quadrant)
int quadrantStep(const Vec3& a, const Vec3& b) {
  const int step = (quadrant(b) - quadrant(a) + 4) % 4;
  return step == 3 ? -1 : step;
}

std::vector<std::array<int, 2>> woundRuns(const tools::Forceps& forceps, const suture::Sleeve& hull,
                                          const ThreadNearJaws& thread,
                                          const std::array<int, 2>& held) {
  std::vector<std::array<int, 2>> runs;
  const double length = tools::jawLength(forceps.def());
  const Eigen::Isometry3d toTool = forceps.pose().inverse();
  const int nodes = static_cast<int>(thread.x.cols());
  int first = -1;
  int quarters = 0;  // the run's winding in quadrant boundaries crossed, signed
  Vec3 last = Vec3::Zero();
  const auto close = [&](int end) {
    if (first >= 0 && std::abs(quarters) >= kWoundQuarterTurns) runs.push_back({first, end});
    first = -1;
  };
  for (int i = std::max(thread.firstThreadNode, 0); i < nodes; ++i) {
    const Vec3 p = thread.x.col(i);
    const Vec3 q = toTool * p;
    // on the jaws: between tip and hinge, outside them (not between them, not held in them),
    // near their surface
    const auto nearSurface = [&] {
      const double off = suture::hullOffset(hull, p, p).distance;
      return off > -kPressedDepth && off <= thread.radius + kCaptureMargin;
    };
    const bool onJaws =
        q.x() >= 0.0 && q.x() <= length && (i < held[0] || i > held[1]) && nearSurface();
    const bool linked = i > 0 && thread.alive[static_cast<std::size_t>(i - 1)];
    // a link across the axis (two quadrants at once) goes through the jaws, not round them
    const bool across = onJaws && first >= 0 && std::abs(quadrantStep(last, q)) == 2;
    if (!onJaws || !linked || across) close(i - 1);
    if (!onJaws) continue;
    // the winding about the tool's axis (tip to hinge), counted in quadrants of its (y, z)
    // plane: signs only, so no machine's maths library can tell it otherwise
    if (first < 0) {
      first = i;
      quarters = 0;
    } else {
      quarters += quadrantStep(last, q);
    }
    last = q;
  }
  close(nodes - 1);
  return runs;
}

}  // namespace

std::vector<std::array<int, 2>> threadWoundOnJaws(const tools::Forceps& forceps,
                                                  const ThreadNearJaws& thread) {
  const std::array<tools::JawCapsule, 2> jaws = tools::jawCapsules(forceps);
  const std::array<int, 2> held = forceps.holdsSuture()
                                      ? heldRun(forceps, jaws, thread.x, thread.radius)
                                      : std::array<int, 2>{0, -1};
  return woundRuns(forceps, jawHull(jaws), thread, held);
}

void appendThreadJawObstacles(const tools::Forceps& forceps, const ThreadNearJaws& thread,
                              suture::SutureWorld& world) {
  const Points& x = thread.x;
  const std::array<tools::JawCapsule, 2> jaws = tools::jawCapsules(forceps);
  // what passes through: the held run while holding (capsules at full size), else nothing
  // (capsules thinned to leave the thread between opened jaws clear)
  std::array<int, 2> held{0, -1};
  std::vector<Vec3> between;
  if (forceps.holdsSuture()) {
    held = heldRun(forceps, jaws, x, thread.radius);
  } else {
    if (!forceps.closed() && needleAtJaws(jaws, x, thread.freeNeedleSwage, kNeedleReach)) return;
    between = threadBetweenJaws(forceps, halfRadii(jaws[0]), x);
  }
  for (const tools::JawCapsule& jaw : jaws) {
    for (const suture::Capsule& half : jawHalves(jaw)) {
      suture::Capsule c = clearOf(half.a, half.b, half.radius, between, thread.radius);
      c.freeFirst = held[0];
      c.freeLast = held[1];
      world.capsules.push_back(c);
    }
  }
  const suture::Sleeve hull = jawHull(jaws);
  for (const std::array<int, 2>& run : woundRuns(forceps, hull, thread, held)) {
    suture::Sleeve sleeve = hull;
    sleeve.first = run[0];
    sleeve.last = run[1];
    world.sleeves.push_back(sleeve);
  }
}

}  // namespace microsim::sim
