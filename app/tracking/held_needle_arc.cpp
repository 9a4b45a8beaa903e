#include "tracking/held_needle_arc.h"

#include "microsim/sim/collide/segment_segment.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <limits>

namespace microsim::tracking {

namespace {

Eigen::Vector3d sutureNode(const sim::RenderSnapshot& s, int i) {
  const auto k = 3 * static_cast<std::size_t>(i);
  return {s.suturePositions[k], s.suturePositions[k + 1], s.suturePositions[k + 2]};
}

// the centre of the circle through a, b and c (null when they are nearly on one line)
std::optional<Eigen::Vector3d> circumcentre(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                            const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a;
  const Eigen::Vector3d ac = c - a;
  const Eigen::Vector3d n = ab.cross(ac);
  const double n2 = n.squaredNorm();
  if (n2 < 1e-12 * ab.squaredNorm() * ac.squaredNorm()) return std::nullopt;
  return a + (ac.squaredNorm() * n.cross(ab) + ab.squaredNorm() * ac.cross(n)) / (2.0 * n2);
}

}  // namespace

std::optional<HeldNeedleArc> heldNeedleArc(const sim::RenderSnapshot& snapshot, sim::Hand hand) {
  const sim::ToolSnapshot& tool = snapshot.forceps[static_cast<std::size_t>(hand)];
  const int nodes = static_cast<int>(snapshot.suturePositions.size() / 3);
  const int needleNodes = std::min(snapshot.needleNodes, nodes);
  if (!tool.present || !tool.holdsSuture || needleNodes < 3) return std::nullopt;
  const Eigen::Affine3d pose(tool.pose.cast<double>());
  const Eigen::Vector3d tip = pose.translation();
  const Eigen::Vector3d heel = pose * Eigen::Vector3d(kHeldNeedleJawReachMm, 0.0, 0.0);

  // a needle link on the jaws' axis: the grip holds the needle there, rigidly
  double nearest = std::numeric_limits<double>::infinity();
  for (int i = 0; i + 1 < needleNodes; ++i)
    nearest = std::min(nearest, sim::collide::closestSegmentSegment(sutureNode(snapshot, i), sutureNode(snapshot, i + 1), tip, heel).distance);
  if (nearest > kHeldNeedleGapMm) return std::nullopt;  // the thread, not the needle

  const Eigen::Vector3d first = sutureNode(snapshot, 0);
  const Eigen::Vector3d second = sutureNode(snapshot, 1);
  const std::optional<Eigen::Vector3d> centre =
      circumcentre(first, sutureNode(snapshot, (needleNodes - 1) / 2), sutureNode(snapshot, needleNodes - 1));
  if (!centre) return std::nullopt;
  // the tip runs forward from node 1 to node 0; the axis turns it that way
  const Eigen::Vector3d axis = (first - *centre).cross(first - second);
  if (axis.squaredNorm() < 1e-18) return std::nullopt;
  const Eigen::Affine3d toTool = pose.inverse();
  HeldNeedleArc arc;
  arc.centre = toTool * *centre;
  arc.axis = (toTool.linear() * axis.normalized()).normalized();
  arc.radius = (first - *centre).norm();
  return arc;
}

}  // namespace microsim::tracking
