// What lies between the jaws (tools/jaw_grasp.h): the region of the shipped jaws, and a face
// and a chain across it.
#include "microsim/sim/tools/jaw_grasp.h"

#include "microsim/sim/tools/forceps.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <string>
#include <variant>
#include <vector>

namespace microsim::sim::tools {
namespace {

const std::string kJawGraspResources = std::string(MICROSIM_SOURCE_DIR) + "/resources/";

/// The right hand's forceps of a scene that uses the shipped jaw mesh.
ForcepsDef jawGraspShippedDef() {
  const std::string text = R"({"objects": [{"type": "lattice", "size": [2, 2, 2]}],
    "tools": {"forceps": [{"hand": "right", "mesh": "forceps_jaw.obj"}]}})";
  SceneDefLoad load = parseSceneDef(text, "grasp.json", kJawGraspResources + "meshes");
  EXPECT_TRUE(std::holds_alternative<SceneDef>(load));
  return *std::get<SceneDef>(load).forceps[static_cast<std::size_t>(Hand::Right)];
}

/// A turned and shifted tool pose, so that nothing lines up with the scene's axes by chance.
Eigen::Isometry3d jawGraspPose() {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translate(Vec3(0.4, -1.1, 2.3));
  pose.rotate(Eigen::AngleAxisd(0.9, Vec3(2.0, -1.0, 0.5).normalized()));
  return pose;
}

/// The shipped jaws' gripping half-width at tool x (mm).
double jawGraspWidth(const ForcepsDef& def, double x) {
  const std::array<double, 2> w = jawHalfWidths(def);
  return w[0] + (w[1] - w[0]) * x / jawLength(def);
}

TEST(JawGrasp, ShippedJawsGripOverTheirFacesHalfWidth) {
  const ForcepsDef def = jawGraspShippedDef();
  // the mesh's gripping face: 0.08 mm wide at the tip, 0.24 mm at the heel (read in single
  // precision)
  const std::array<double, 2> w = jawHalfWidths(def);
  EXPECT_NEAR(w[0], 0.04, 1e-7);
  EXPECT_NEAR(w[1], 0.12, 1e-7);
}

TEST(JawGrasp, TheRegionIsTheSectorTheJawsSweepAsWideAsTheirFaces) {
  const ForcepsDef def = jawGraspShippedDef();
  const Eigen::Isometry3d pose = jawGraspPose();
  const double length = jawLength(def);
  const auto in = [&](const GraspRegion& r, double x, double y, double z) {
    return insideGraspRegion(r, pose * Vec3(x, y, z));
  };
  for (const double closure : {0.0, 0.7}) {
    SCOPED_TRACE(closure);
    const double theta = jawAngle(def, closure);
    const GraspRegion r = graspRegion(def, pose, closure, 0.0);
    // between the gripping faces, and not past them
    const double gap = (length - 1.5) * std::tan(theta);
    EXPECT_TRUE(in(r, 1.5, 0.0, 0.0));
    EXPECT_TRUE(in(r, 1.5, 0.99 * gap, 0.0));
    EXPECT_TRUE(in(r, 1.5, -0.99 * gap, 0.0));
    EXPECT_FALSE(in(r, 1.5, 1.01 * gap, 0.0));
    EXPECT_FALSE(in(r, 1.5, -1.01 * gap, 0.0));
    // as wide as the faces
    EXPECT_TRUE(in(r, 1.5, 0.0, 0.99 * jawGraspWidth(def, 1.5)));
    EXPECT_FALSE(in(r, 1.5, 0.0, 1.01 * jawGraspWidth(def, 1.5)));
    EXPECT_FALSE(in(r, 1.5, 0.0, -1.01 * jawGraspWidth(def, 1.5)));
    // from the arc the tips run along to the hinge
    EXPECT_TRUE(in(r, 0.001, 0.0, 0.0));
    EXPECT_FALSE(in(r, -0.001, 0.0, 0.0));
    EXPECT_TRUE(in(r, length - 0.001, 0.0, 0.0));
    EXPECT_FALSE(in(r, length + 0.001, 0.0, 0.0));
    const Vec3 tip = pose.inverse() * jawTips(def, pose, closure)[0];
    EXPECT_TRUE(in(r, tip.x() + 0.001, tip.y() - 0.002, 0.0));
    EXPECT_FALSE(in(r, tip.x() - 0.001, tip.y(), 0.0));
  }
  // a margin widens it every way
  const GraspRegion wide = graspRegion(def, pose, 0.7, 0.01);
  EXPECT_TRUE(in(wide, -0.009, 0.0, 0.0));
  EXPECT_TRUE(in(wide, 1.5, 0.0, jawGraspWidth(def, 1.5) + 0.009));
  EXPECT_FALSE(in(wide, -0.011, 0.0, 0.0));
}

// one triangle of a tissue, corners given in the tool frame of `pose`
SpringModel jawGraspTriangle(const Eigen::Isometry3d& pose, const Vec3& a, const Vec3& b, const Vec3& c) {
  SpringModel m;
  m.addNode(pose * a);
  m.addNode(pose * b);
  m.addNode(pose * c);
  m.addTriangle(0, 1, 2);
  return m;
}

TEST(JawGrasp, AFaceAcrossTheJawsIsHeldAtTheCentroidOfItsPartBetweenThem) {
  const ForcepsDef def = jawGraspShippedDef();
  const Eigen::Isometry3d pose = jawGraspPose();
  const double closure = 0.6;
  const GraspRegion region = graspRegion(def, pose, closure, 0.0);
  // a face across the jaws at x = 1 mm, far larger than their cross-section there: its part
  // between them is that cross-section, a rectangle centred on the tool's axis
  SpringModel across = jawGraspTriangle(pose, Vec3(1, -2, -2), Vec3(1, 2, -2), Vec3(1, 0, 3));
  across.finalize();
  const std::vector<FaceGrasp> held = facesBetweenJaws(region, across, across.restPositions());
  ASSERT_EQ(held.size(), 1u);
  const Vec3 point = across.restPositions() * held[0].barycentric;
  EXPECT_LT((point - pose * Vec3(1, 0, 0)).norm(), 1e-12);
  EXPECT_NEAR(held[0].barycentric.sum(), 1.0, 1e-15);
  const double width = jawGraspWidth(def, 1.0);
  const double gap = (jawLength(def) - 1.0) * std::tan(jawAngle(def, closure));
  EXPECT_NEAR(held[0].area, 2.0 * gap * 2.0 * width, 1e-12);

  // the same face beside the jaws, one with a corner skipped, one that cannot move: nothing
  SpringModel beside = jawGraspTriangle(pose, Vec3(1, -2, 0.2), Vec3(1, 2, 0.2), Vec3(1, 0, 3));
  beside.finalize();
  EXPECT_TRUE(facesBetweenJaws(region, beside, beside.restPositions()).empty());
  EXPECT_TRUE(facesBetweenJaws(region, across, across.restPositions(), {0, 1, 0}).empty());
  SpringModel fixed = jawGraspTriangle(pose, Vec3(1, -2, -2), Vec3(1, 2, -2), Vec3(1, 0, 3));
  for (int i = 0; i < 3; ++i) fixed.setFixed(i);
  fixed.finalize();
  EXPECT_TRUE(facesBetweenJaws(region, fixed, fixed.restPositions()).empty());
}

TEST(JawGrasp, AChainAcrossTheJawsIsTakenWhereItCrossesTheLineTheyMeetOn) {
  const ForcepsDef def = jawGraspShippedDef();
  const Eigen::Isometry3d pose = jawGraspPose();
  const GraspRegion region = graspRegion(def, pose, 0.5, 0.01);
  // nodes along the jaws' width at x = 1.2: link 1 crosses the axis three quarters along
  Points x(3, 4);
  const double zs[4] = {-0.35, -0.15, 0.05, 0.25};
  for (int i = 0; i < 4; ++i) x.col(i) = pose * Vec3(1.2, 0.0, zs[i]);
  const std::optional<ChainGrasp> at = chainPointBetweenJaws(region, x);
  ASSERT_TRUE(at.has_value());
  EXPECT_EQ(at->link, 1);
  EXPECT_NEAR(at->fraction, 0.75, 1e-12);
  EXPECT_LT(at->distance, 1e-12);

  // link 1 broken: what is left between the jaws is the start of link 2
  const std::optional<ChainGrasp> broken = chainPointBetweenJaws(region, x, {1, 0, 1});
  ASSERT_TRUE(broken.has_value());
  EXPECT_EQ(broken->link, 2);
  EXPECT_NEAR(broken->fraction, 0.0, 1e-12);
  EXPECT_NEAR(broken->distance, 0.05, 1e-12);

  // moved past the jaws' width: nothing
  for (int i = 0; i < 4; ++i) x.col(i) = pose * Vec3(1.2, 0.5, zs[i]);
  EXPECT_FALSE(chainPointBetweenJaws(region, x).has_value());
}

}  // namespace
}  // namespace microsim::sim::tools
