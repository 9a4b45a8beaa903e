#include "microsim/sim/tools/microscissors.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace microsim::sim::tools {

namespace {

constexpr double kDegToRad = 3.14159265358979323846 / 180.0;

/// 2D cross product of (b − a) and (c − a): > 0 when c lies left of a → b.
double scissorsOrient(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  const Eigen::Vector2d u = b - a, v = c - a;
  return u.x() * v.y() - u.y() * v.x();
}

bool insideTriangle2d(const std::array<Eigen::Vector2d, 3>& t, const Eigen::Vector2d& p) {
  const double d0 = scissorsOrient(t[0], t[1], p), d1 = scissorsOrient(t[1], t[2], p),
               d2 = scissorsOrient(t[2], t[0], p);
  return (d0 >= 0.0 && d1 >= 0.0 && d2 >= 0.0) || (d0 <= 0.0 && d1 <= 0.0 && d2 <= 0.0);
}

bool segmentsCross2d(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                     const Eigen::Vector2d& d) {
  const double o1 = scissorsOrient(a, b, c), o2 = scissorsOrient(a, b, d);
  const double o3 = scissorsOrient(c, d, a), o4 = scissorsOrient(c, d, b);
  return ((o1 > 0.0) != (o2 > 0.0)) && ((o3 > 0.0) != (o4 > 0.0));
}

/// Where the link a → b (tool frame) passes through the prism {triangle t} × [−h, h], as the
/// point of its part inside that passes nearest y = 0; none when it misses.
std::optional<Vec3> linkThroughPrism(const Vec3& a, const Vec3& b, const std::array<Eigen::Vector2d, 3>& t,
                                     double h) {
  // clip the segment to the slab |z| ≤ h
  double t0 = 0.0, t1 = 1.0;
  const double dz = b.z() - a.z();
  if (std::abs(dz) < 1e-15) {
    if (std::abs(a.z()) > h) return std::nullopt;
  } else {
    double s0 = (-h - a.z()) / dz, s1 = (h - a.z()) / dz;
    if (s0 > s1) std::swap(s0, s1);
    t0 = std::max(t0, s0);
    t1 = std::min(t1, s1);
    if (t0 > t1) return std::nullopt;
  }
  const Vec3 p = a + t0 * (b - a), q = a + t1 * (b - a);
  const Eigen::Vector2d p2 = p.head<2>(), q2 = q.head<2>();
  const bool meets = insideTriangle2d(t, p2) || insideTriangle2d(t, q2) || segmentsCross2d(p2, q2, t[0], t[1]) ||
                     segmentsCross2d(p2, q2, t[1], t[2]) || segmentsCross2d(p2, q2, t[2], t[0]);
  if (!meets) return std::nullopt;
  // the point of the clipped part nearest y = 0 (where it crosses y = 0, else its nearer end)
  if ((p.y() > 0.0) != (q.y() > 0.0) && std::abs(q.y() - p.y()) > 0.0) {
    const double s = p.y() / (p.y() - q.y());
    return Vec3(p + s * (q - p));
  }
  return std::abs(p.y()) <= std::abs(q.y()) ? p : q;
}

/// Arc length from `from` along the chain in direction `step` (±1) starting at node `node`,
/// to the first anchor, within intact links; none when the piece ends first.
std::optional<double> arcToAnchor(const Points& chain, const std::vector<std::uint8_t>& alive, const Vec3& from,
                                  int node, int step, const std::vector<std::uint8_t>& isAnchor) {
  double length = (chain.col(node) - from).norm();
  const int last = static_cast<int>(chain.cols()) - 1;
  while (true) {
    if (isAnchor[static_cast<std::size_t>(node)]) return length;
    const int next = node + step;
    if (next < 0 || next > last) return std::nullopt;
    const int link = std::min(node, next);
    if (!alive[static_cast<std::size_t>(link)]) return std::nullopt;
    length += (chain.col(next) - chain.col(node)).norm();
    node = next;
  }
}

std::vector<std::uint8_t> anchorMask(Eigen::Index nodes, const std::vector<int>& anchorNodes) {
  std::vector<std::uint8_t> mask(static_cast<std::size_t>(nodes), 0);
  for (int n : anchorNodes)
    if (n >= 0 && n < nodes) mask[static_cast<std::size_t>(n)] = 1;
  return mask;
}

}  // namespace

std::array<Vec3, 2> scissorsBladeTips(const ScissorsDef& def, double closure) {
  const double theta = (1.0 - std::clamp(closure, 0.0, 1.0)) * def.openingDeg * kDegToRad;
  const double l = def.bladeLength;
  return {Vec3(l - l * std::cos(theta), l * std::sin(theta), 0.0), Vec3(l - l * std::cos(theta), -l * std::sin(theta), 0.0)};
}

std::array<Eigen::Isometry3d, 2> scissorsBladePoses(const ScissorsDef& def, const Eigen::Isometry3d& pose,
                                                    double closure) {
  const double theta = (1.0 - std::clamp(closure, 0.0, 1.0)) * def.openingDeg * kDegToRad;
  const Vec3 pivot(def.bladeLength, 0.0, 0.0);
  std::array<Eigen::Isometry3d, 2> out;
  for (std::size_t b = 0; b < 2; ++b) {
    // turn about the pivot; the lower blade is the mirror image
    Eigen::Isometry3d blade = Eigen::Isometry3d::Identity();
    blade.translate(pivot);
    blade.rotate(Eigen::AngleAxisd(b == 0 ? -theta : theta, Vec3::UnitZ()));
    blade.translate(-pivot);
    if (b == 1) blade.linear() = blade.linear() * Eigen::Vector3d(1.0, -1.0, 1.0).asDiagonal();
    out[b] = pose * blade;
  }
  return out;
}

std::vector<ThreadCut> scissorsCuts(const ScissorsDef& def, const Eigen::Isometry3d& pose, double closureFrom,
                                    double closureTo, const Points& chain, const std::vector<std::uint8_t>& alive,
                                    int firstThreadLink, double threadRadius) {
  std::vector<ThreadCut> cuts;
  if (!(closureFrom < def.cutAt && closureTo >= def.cutAt)) return cuts;
  const std::array<Vec3, 2> tips = scissorsBladeTips(def, closureFrom);
  const std::array<Eigen::Vector2d, 3> wedge = {Eigen::Vector2d(def.bladeLength, 0.0), tips[0].head<2>(),
                                                tips[1].head<2>()};
  const double h = def.bladeHalfThickness + threadRadius;
  const Eigen::Isometry3d toTool = pose.inverse();

  // runs of consecutive links through the wedge; each run is one strand, cut once
  const int links = static_cast<int>(chain.cols()) - 1;
  int best = -1;
  double bestY = std::numeric_limits<double>::infinity();
  Vec3 bestPoint = Vec3::Zero();
  const auto endRun = [&] {
    if (best >= 0) cuts.push_back({best, pose * bestPoint});
    best = -1;
    bestY = std::numeric_limits<double>::infinity();
  };
  for (int i = std::max(0, firstThreadLink); i < links; ++i) {
    const std::optional<Vec3> at =
        alive[static_cast<std::size_t>(i)] ? linkThroughPrism(toTool * chain.col(i), toTool * chain.col(i + 1), wedge, h)
                                           : std::nullopt;
    if (!at) {
      endRun();
      continue;
    }
    if (std::abs(at->y()) < bestY) {
      best = i;
      bestY = std::abs(at->y());
      bestPoint = *at;
    }
  }
  endRun();
  return cuts;
}

std::optional<double> cutEndLength(const Points& chain, const std::vector<std::uint8_t>& alive, const ThreadCut& cut,
                                   const std::vector<int>& anchorNodes) {
  const std::vector<std::uint8_t> isAnchor = anchorMask(chain.cols(), anchorNodes);
  const std::optional<double> back = arcToAnchor(chain, alive, cut.point, cut.link, -1, isAnchor);
  const std::optional<double> ahead = arcToAnchor(chain, alive, cut.point, cut.link + 1, +1, isAnchor);
  if (back && ahead) return std::min(*back, *ahead);
  return back ? back : ahead;
}

double threadOnNeedle(const Points& chain, const std::vector<std::uint8_t>& alive, int swage) {
  double length = 0.0;
  const int last = static_cast<int>(chain.cols()) - 1;
  for (int node = std::max(swage, 0); node < last && alive[static_cast<std::size_t>(node)]; ++node)
    length += (chain.col(node + 1) - chain.col(node)).norm();
  return length;
}

bool onNeedlePiece(const std::vector<std::uint8_t>& alive, int swage, int link) {
  if (link < swage || link >= static_cast<int>(alive.size())) return false;
  for (int i = std::max(swage, 0); i <= link; ++i)
    if (!alive[static_cast<std::size_t>(i)]) return false;
  return true;
}

}  // namespace microsim::sim::tools
