// The forceps' jaws against the tissue (tools/jaw_contact.h): the capsules of the shipped jaw
// mesh, which nodes get a spring, which way it pushes, and a solve against it.
#include "microsim/sim/tools/jaw_contact.h"

#include "microsim/sim/scene/scene_def.h"
#include "microsim/sim/solve/solver.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <string>
#include <variant>
#include <vector>

namespace microsim::sim::tools {
namespace {

/// The right hand's forceps of a scene that uses the shipped jaw mesh.
ForcepsDef jawContactShippedDef() {
  const std::string text = R"({"objects": [{"type": "lattice", "size": [3, 3, 3], "stiffness": 10}],
    "tools": {"forceps": [{"hand": "right", "mesh": "forceps_jaw.obj"}]}})";
  SceneDefLoad load =
      parseSceneDef(text, "jaw.json", std::string(MICROSIM_SOURCE_DIR) + "/resources/meshes");
  EXPECT_TRUE(std::holds_alternative<SceneDef>(load));
  const auto& forceps = std::get<SceneDef>(load).forceps[static_cast<std::size_t>(Hand::Right)];
  EXPECT_TRUE(forceps.has_value());
  return *forceps;
}

/// Distance of p from the capsule's axis and the capsule's radius at p's place along it (mm).
std::pair<double, double> jawContactRadial(const JawCapsule& c, const Vec3& p) {
  const Vec3 axis = c.heel - c.tip;
  const double s = std::clamp((p - c.tip).dot(axis) / axis.squaredNorm(), 0.0, 1.0);
  return {(p - (c.tip + s * axis)).norm(), c.tipRadius + s * (c.heelRadius - c.tipRadius)};
}

/// The shipped forceps, open (closure 0), at a turned and shifted pose.
Forceps jawContactForceps(const ForcepsDef& def) {
  Forceps forceps(def);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translate(Vec3(1.0, -2.0, 0.5));
  pose.rotate(Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, 3.0).normalized()));
  bool released = false;
  forceps.update(pose, 0.0, 1.0, released);
  return forceps;
}

TEST(JawContact, ShippedJawRadiiArePositiveAndGrowToTheHeel) {
  const ForcepsDef def = jawContactShippedDef();
  ASSERT_GT(def.jawVertices.cols(), 0);
  const std::array<double, 2> radii = jawRadii(def);
  EXPECT_GT(radii[0], 0.0);
  EXPECT_GE(radii[1], radii[0]);
  // the mesh's end faces: 0.08 by 0.03 mm at the tip, 0.24 by 0.15 mm at the heel, gripping
  // face on y = 0, so the farthest corners are (0.03, ±0.04) and (0.15, ±0.12) off the axis
  // (the mesh is read in single precision)
  EXPECT_NEAR(radii[0], std::hypot(0.03, 0.04), 1e-7);
  EXPECT_NEAR(radii[1], std::hypot(0.15, 0.12), 1e-7);
}

TEST(JawContact, CapsulesEncloseTheJawsAndEndAtTheirTips) {
  const ForcepsDef def = jawContactShippedDef();
  for (double closure : {0.0, 0.5, 1.0}) {
    SCOPED_TRACE(closure);
    Forceps forceps = jawContactForceps(def);
    bool released = false;
    forceps.update(forceps.pose(), closure, 1.0, released);
    const std::array<JawCapsule, 2> capsules = jawCapsules(forceps);
    const std::array<Vec3, 2> tips = forceps.tips();
    const Points v = jawVertices(def, forceps.pose(), closure);
    const Eigen::Index n = def.jawVertices.cols();
    for (std::size_t j = 0; j < 2; ++j) {
      EXPECT_LT((capsules[j].tip - tips[j]).norm(), 1e-12);
      EXPECT_NEAR((capsules[j].heel - capsules[j].tip).norm(), jawLength(def), 1e-12);
      for (Eigen::Index i = 0; i < n; ++i) {
        const auto [distance, radius] = jawContactRadial(capsules[j], v.col(static_cast<Eigen::Index>(j) * n + i));
        EXPECT_LE(distance, radius + 1e-12) << "jaw " << j << " vertex " << i;
      }
    }
  }
}

// One triangle across a jaw, halfway into it: wound to face the jaw's axis it is pushed back
// out along its inward normal; wound the other way (the wall's far side), with a held node, or
// far away, it gets nothing.
SpringModel jawContactTriangle(const Vec3& centre, const Vec3& along, const Vec3& across, bool facing,
                               const Vec3& towardsAxis) {
  SpringModel m;
  m.addNode(centre + 0.02 * along);
  m.addNode(centre - 0.01 * along + 0.02 * across);
  m.addNode(centre - 0.01 * along - 0.02 * across);
  const Vec3 n = (m.restPositions().col(1) - m.restPositions().col(0)).cross(m.restPositions().col(2) - m.restPositions().col(0));
  const bool wound = n.dot(towardsAxis) > 0.0;
  if (wound == facing)
    m.addTriangle(0, 1, 2);
  else
    m.addTriangle(0, 2, 1);
  m.finalize();
  return m;
}

TEST(JawContact, FacesInFrontOfAJawArePushedBackAndOthersIgnored) {
  const ForcepsDef def = jawContactShippedDef();
  const Forceps forceps = jawContactForceps(def);
  const JawCapsule upper = jawCapsules(forceps)[0];
  const Vec3 axis = (upper.heel - upper.tip).normalized();
  const Vec3 side = axis.unitOrthogonal();
  const Vec3 across = axis.cross(side);
  const Vec3 middle = 0.5 * (upper.tip + upper.heel);
  const double radius = 0.5 * (upper.tipRadius + upper.heelRadius);
  const double reach = 0.05;
  const double k = 300.0;
  const Vec3 centre = middle + 0.5 * radius * side;

  const SpringModel facing = jawContactTriangle(centre, axis, across, true, -side);
  const Points x = facing.restPositions();
  std::vector<PointSpring> springs;
  appendJawContacts(forceps, facing, x, {}, reach, k, springs);
  ASSERT_FALSE(springs.empty());
  for (const PointSpring& s : springs) {
    ASSERT_TRUE(s.oneSided());
    EXPECT_EQ(s.size(), 3);
    EXPECT_EQ(s.k, k);
    EXPECT_NEAR(s.normal.dot(side), 1.0, 1e-9);  // back into its wall, away from the axis
    const Vec3 f = pointSpringForce(s, pointSpringOffset(s, x));
    EXPECT_GT(f.dot(side), 0.0);
    EXPECT_NEAR(s.weights[0] + s.weights[1] + s.weights[2], 1.0, 1e-9);
  }

  springs.clear();
  const SpringModel away = jawContactTriangle(centre, axis, across, false, -side);
  appendJawContacts(forceps, away, away.restPositions(), {}, reach, k, springs);
  EXPECT_TRUE(springs.empty());

  springs.clear();
  std::vector<std::uint8_t> held(3, 0);
  held[1] = 1;
  appendJawContacts(forceps, facing, x, held, reach, k, springs);
  EXPECT_TRUE(springs.empty());

  springs.clear();
  const SpringModel far = jawContactTriangle(middle + 10.0 * side, axis, across, true, -side);
  appendJawContacts(forceps, far, far.restPositions(), {}, reach, k, springs);
  EXPECT_TRUE(springs.empty());
}

// A jaw's tip in the corner of a cut end: the outer face and the cut face meet at the rim at
// a right angle, the tip's axis just inside both. Each face is pushed straight away from the
// axis, the way it lies from it, so the two never push the rim against itself (with the faces'
// own normals the cut face pushed the rim along the vessel and the outer face pushed it into
// the wall, and the rim swung from one to the other between steps).
TEST(JawContact, FacesRoundATipInACornerArePushedAwayFromTheAxis) {
  const ForcepsDef def = jawContactShippedDef();
  const Forceps forceps = jawContactForceps(def);
  const JawCapsule upper = jawCapsules(forceps)[0];
  const Vec3 axis = (upper.heel - upper.tip).normalized();
  const Vec3 u = axis.unitOrthogonal();
  const Vec3 w = axis.cross(u);
  // the rim runs along w through a point 0.02 mm from the tip along −u and −axis; both faces
  // look towards the jaw: the outer face along u, the cut face along the axis
  const Vec3 rim = upper.tip - 0.02 * u - 0.02 * axis;
  SpringModel m;
  m.addNode(rim - 0.2 * w);
  m.addNode(rim + 0.2 * w);
  m.addNode(rim - 0.3 * u);     // the cut face's far edge, into the wall
  m.addNode(rim + 0.3 * axis);  // the outer face's far edge, along the jaw
  const auto facing = [&](int a, int b, int c, const Vec3& towards) {
    const Points& r = m.restPositions();
    const Vec3 n = (r.col(b) - r.col(a)).cross(r.col(c) - r.col(a));
    if (n.dot(towards) > 0.0)
      m.addTriangle(a, b, c);
    else
      m.addTriangle(a, c, b);
  };
  facing(0, 1, 2, axis);  // the cut face, in the plane across the axis
  facing(0, 1, 3, u);     // the outer face, in the plane along it
  m.finalize();
  const Points x = m.restPositions();
  std::vector<PointSpring> springs;
  appendJawContacts(forceps, m, x, {}, 0.05, 300.0, springs);
  ASSERT_EQ(springs.size(), 2u) << "both faces are within reach";
  for (const PointSpring& s : springs) {
    ASSERT_TRUE(s.oneSided());
    const Vec3 point = pointSpringOffset(s, x) + s.anchor;
    const Vec3 away = (point - s.anchor).normalized();
    EXPECT_NEAR(s.normal.dot(away), 1.0, 1e-9) << "pushed straight away from the axis";
    EXPECT_GT(pointSpringForce(s, pointSpringOffset(s, x)).dot(away), 0.0);
  }
}

}  // namespace
}  // namespace microsim::sim::tools
