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
  forceps.update(pose, 0.0, released);
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
    forceps.update(forceps.pose(), closure, released);
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

TEST(JawContact, NodesInsideAJawArePushedOutAndFarOnesIgnored) {
  const ForcepsDef def = jawContactShippedDef();
  const Forceps forceps = jawContactForceps(def);
  const JawCapsule upper = jawCapsules(forceps)[0];
  const Vec3 axis = (upper.heel - upper.tip).normalized();
  const Vec3 side = axis.unitOrthogonal();
  const Vec3 middle = 0.5 * (upper.tip + upper.heel);
  const double radius = 0.5 * (upper.tipRadius + upper.heelRadius);
  const double reach = 0.05;
  const double k = 300.0;

  // on the axis, halfway out, just outside within reach, beyond the tip, far away
  Points x(3, 5);
  x.col(0) = middle;
  x.col(1) = middle + 0.5 * radius * side;
  x.col(2) = middle + (radius + 0.5 * reach) * side;
  x.col(3) = upper.tip - 0.5 * upper.tipRadius * axis;
  x.col(4) = middle + Vec3(10.0, 10.0, 10.0);
  std::vector<PointSpring> springs;
  appendJawContacts(forceps, x, {0, 1, 2, 3, 4}, {}, reach, k, springs);
  ASSERT_EQ(springs.size(), 4u);
  std::array<int, 5> count{};
  for (const PointSpring& s : springs) {
    ASSERT_EQ(s.size(), 1);
    ASSERT_TRUE(s.oneSided());
    EXPECT_EQ(s.k, k);
    ++count[static_cast<std::size_t>(s.nodes[0])];
    const int node = s.nodes[0];
    const Vec3 f = pointSpringForce(s, pointSpringOffset(s, x));
    switch (node) {
      case 0:  // across the jaw, by k times the radius
        EXPECT_NEAR(f.norm(), k * radius, 1e-9);
        EXPECT_NEAR(f.dot(axis), 0.0, 1e-9);
        break;
      case 1:  // out along its offset, by k times what it lacks of the radius
        EXPECT_LT((f - k * 0.5 * radius * side).norm(), 1e-9);
        break;
      case 2:  // outside: watched, not pushed
        EXPECT_TRUE(f.isZero(0.0));
        break;
      case 3:  // beyond the tip: pushed on along the axis
        EXPECT_LT((f + k * 0.5 * upper.tipRadius * axis).norm(), 1e-9);
        break;
      default:
        ADD_FAILURE() << "node " << node;
    }
    // moved by f / k, a pressed node lands on the capsule's surface
    if (!f.isZero(0.0)) {
      const auto [distance, r] = jawContactRadial(upper, x.col(node) + f / k);
      EXPECT_NEAR(distance, r, 1e-9) << "node " << node;
    }
  }
  EXPECT_EQ(count, (std::array<int, 5>{1, 1, 1, 1, 0}));

  // marked nodes get none; the rest as before
  std::vector<std::uint8_t> skip(5, 0);
  skip[0] = skip[1] = 1;
  springs.clear();
  appendJawContacts(forceps, x, {0, 1, 2, 3, 4}, skip, reach, k, springs);
  ASSERT_EQ(springs.size(), 2u);
  EXPECT_EQ(springs[0].nodes[0], 2);
  EXPECT_EQ(springs[1].nodes[0], 3);
  // nodes not listed get none either
  springs.clear();
  appendJawContacts(forceps, x, {4}, {}, reach, k, springs);
  EXPECT_TRUE(springs.empty());
}

TEST(JawContact, NewtonHoldsATetheredNodeOnTheJawSurface) {
  // a node tethered by a zero-rest link (k_l) to a fixed node on the jaw's axis, started
  // inside the jaw: it settles where the link's pull and the jaw's push balance, at
  // k_c r / (k_c + k_l) from the axis
  const ForcepsDef def = jawContactShippedDef();
  const Forceps forceps = jawContactForceps(def);
  const JawCapsule upper = jawCapsules(forceps)[0];
  const Vec3 axis = (upper.heel - upper.tip).normalized();
  const Vec3 side = axis.unitOrthogonal();
  const Vec3 middle = 0.5 * (upper.tip + upper.heel);
  const double radius = 0.5 * (upper.tipRadius + upper.heelRadius);
  const double kl = 1.0, kc = 1000.0;

  SpringModel model;
  model.addNode(middle);
  model.addNode(middle + 0.3 * radius * side);
  model.addLink(0, 1, kl, 0.0);
  model.setFixed(0);
  model.finalize();
  SpringState state = SpringState::atRest(model);
  SpringControls controls;
  appendJawContacts(forceps, state.x, {1}, {}, 0.05, kc, controls.springs);
  ASSERT_EQ(controls.springs.size(), 1u);
  for (const char* name : {"newton", "reference"}) {
    SCOPED_TRACE(name);
    SpringState solved = state;
    SolveBudget budget;
    budget.maxIterations = 50;
    budget.residualTolerance = 1e-10;
    EXPECT_EQ(makeSolver(name)->solve(model, solved, controls, budget).status, SolveStatus::Converged);
    EXPECT_LT((solved.x.col(1) - (middle + kc * radius / (kc + kl) * side)).norm(), 1e-9);
  }
}

}  // namespace
}  // namespace microsim::sim::tools
