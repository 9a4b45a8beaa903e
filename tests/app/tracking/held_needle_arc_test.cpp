#include "tracking/held_needle_arc.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace microsim::tracking {
namespace {

constexpr double kArcTestRadius = 0.8;
const Eigen::Vector3d kArcTestCentre(1.0, -2.0, 0.5);

// a 3/8-circle needle of 9 nodes about kArcTestCentre in the plane z = 0.5 (tip at angle 0,
// the body running counter-clockwise seen from +z), then 4 thread nodes straight on; the
// right forceps' jaws (its +x, tip → hinge, along scene +z) closed across needle node
// `gripNode` (or across the thread's second link)
sim::RenderSnapshot needleSnapshot(int gripNode, bool onThread = false) {
  sim::RenderSnapshot s;
  s.needleNodes = 9;
  std::vector<Eigen::Vector3d> nodes;
  for (int k = 0; k < 9; ++k) {
    const double a = 0.75 * std::numbers::pi * k / 8.0;
    nodes.push_back(kArcTestCentre + kArcTestRadius * Eigen::Vector3d(std::cos(a), std::sin(a), 0.0));
  }
  for (int k = 1; k <= 4; ++k) nodes.push_back(nodes.back() + Eigen::Vector3d(-0.2 * k, 0.0, 0.0));
  for (const Eigen::Vector3d& p : nodes)
    s.suturePositions.insert(s.suturePositions.end(), {static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())});
  s.sutureAlive.assign(nodes.size() - 1, 1);
  sim::ToolSnapshot& tool = s.forceps[1];
  tool.present = true;
  tool.holdsSuture = true;
  const Eigen::Vector3d grip = onThread ? 0.5 * (nodes[10] + nodes[11]) : nodes[static_cast<std::size_t>(gripNode)];
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(-0.5 * std::numbers::pi, Eigen::Vector3d::UnitY()).toRotationMatrix();
  pose.translation() = grip - 0.2 * (pose.linear() * Eigen::Vector3d::UnitX());  // the needle 0.2 mm in
  tool.pose = pose.matrix().cast<float>();
  s.forceps[0].present = true;
  return s;
}

Eigen::Isometry3d toolPose(const sim::RenderSnapshot& s) { return Eigen::Isometry3d(s.forceps[1].pose.cast<double>()); }

TEST(HeldNeedleArc, IsTheNeedlesCircleInTheToolFrameWithTheTipForward) {
  const sim::RenderSnapshot s = needleSnapshot(6);
  const std::optional<HeldNeedleArc> arc = heldNeedleArc(s, sim::Hand::Right);
  ASSERT_TRUE(arc.has_value());
  const Eigen::Isometry3d pose = toolPose(s);
  EXPECT_LT((pose * arc->centre - kArcTestCentre).norm(), 1e-5);
  EXPECT_NEAR(arc->radius, kArcTestRadius, 1e-5);
  // the tip (angle 0) runs toward negative angles: clockwise seen from +z, about −z
  EXPECT_LT((pose.linear() * arc->axis - Eigen::Vector3d(0, 0, -1)).norm(), 1e-5);
  // the other hand holds nothing
  EXPECT_FALSE(heldNeedleArc(s, sim::Hand::Left).has_value());
}

TEST(HeldNeedleArc, NoneWhenTheJawsHoldTheThreadOrNothingOrTheNeedleIsStraight) {
  EXPECT_FALSE(heldNeedleArc(needleSnapshot(0, true), sim::Hand::Right).has_value());

  sim::RenderSnapshot open = needleSnapshot(4);
  open.forceps[1].holdsSuture = false;
  EXPECT_FALSE(heldNeedleArc(open, sim::Hand::Right).has_value());

  // the needle straightened along scene x through the same grip
  sim::RenderSnapshot straight = needleSnapshot(4);
  const std::vector<float> grip(straight.suturePositions.begin() + 12, straight.suturePositions.begin() + 15);
  for (std::size_t k = 0; k < 9; ++k) {
    straight.suturePositions[3 * k] = grip[0] + 0.1f * (static_cast<float>(k) - 4.0f);
    straight.suturePositions[3 * k + 1] = grip[1];
    straight.suturePositions[3 * k + 2] = grip[2];
  }
  EXPECT_FALSE(heldNeedleArc(straight, sim::Hand::Right).has_value());
}

}  // namespace
}  // namespace microsim::tracking
