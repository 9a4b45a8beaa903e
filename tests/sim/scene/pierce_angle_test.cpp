// A pierce's angle is the needle's own where its body crosses the wall (Scene::describePierce,
// tools::needleTangentNear): the curved needle turned about its centre through a flat wall at
// 30, 45, 60 and 90° to the surface reads 60, 45, 30 and 0° from the normal, and the shipped
// vessel dented before its puncture reads the angle of the pass's geometry, not the angle the
// tip has turned to by the time the wall gives.
#include "microsim/sim/scene/scene.h"
#include "microsim/sim/scene/stitch_script.h"
#include "microsim/sim/suture/suture_model.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>
#include <string>
#include <variant>
#include <vector>

namespace microsim::sim {
namespace {

constexpr double kAngleTestDeg = std::numbers::pi / 180.0;

// a fixed-border grid of 0.25 mm cells in z = 0 (±2 mm), the shipped needle lying above it
// and a right needle holder; `punctureForce` 0 pierces where the tip meets the grid
SceneDef flatWallScene() {
  const std::string text = R"({"objects": [{"type": "grid", "cells": [16, 16], "size": 0.25,
      "stiffness": 1e5, "mass": 4e-6, "fix_border": true}],
    "solver": {"name": "newton", "iterations": 20, "tolerance": 1e-8},
    "tools": {"forceps": [{"hand": "right", "mesh": "forceps_jaw.obj", "opening_deg": 20}],
      "needle": {"shape": "curved", "radius": 0.8, "needle_links": 8, "links": 60, "thread_length": 8.0,
        "position": [-2.5, 1.5, 1.5], "rotation": [1, 0, 0, 0], "solver": "direct",
        "substeps": 4, "iterations": 2, "puncture_force": 0}}})";
  SceneDefLoad load = parseSceneDef(text, "flat_wall.json", std::string(MICROSIM_SOURCE_DIR) + "/resources/meshes");
  EXPECT_TRUE(std::holds_alternative<SceneDef>(load));
  return std::get<SceneDef>(std::move(load));
}

// the holder on the swage, its jaws across the needle's plane (as the scripted stitch holds it)
Eigen::Isometry3d holderOnSwage(const SceneDef& def) {
  const suture::SutureModel needle(def.needle->suture);
  Eigen::Isometry3d grip = Eigen::Isometry3d::Identity();
  grip.linear() = Eigen::AngleAxisd(-0.5 * std::numbers::pi, Vec3::UnitY()).toRotationMatrix();
  grip.translation() = needle.needleShape().col(needle.needleLinks());
  return grip;
}

InputFrame holderAt(const Eigen::Isometry3d& pose, double closure, int k) {
  InputFrame f;
  f.time = 0.01 * k;
  f.hand(Hand::Left).instrument = Instrument::None;
  HandInput& h = f.hand(Hand::Right);
  h.instrument = Instrument::NeedleHolder;
  h.tracked = true;
  h.position = pose.translation();
  h.orientation = Eigen::Quaterniond(pose.linear()).normalized();
  h.closure = closure;
  return f;
}

/// The first pierce of the needle gripped where it lies, carried to ψ = −β − 30° on a circle in
/// the x–z plane whose tip meets z = 0 at β to the surface (centre R cos β above it), and
/// turned to −β + 25° (through the wall).
std::vector<PierceEvent> turnThroughFlatWall(double surfaceDeg) {
  const SceneDef def = flatWallScene();
  StitchGeometry g;
  g.eu = Vec3::UnitX();
  g.ew = Vec3::UnitZ();
  g.radius = def.needle->suture.needleRadius;
  g.center = Vec3(0.0, 0.0, g.radius * std::cos(surfaceDeg * kAngleTestDeg));
  const Eigen::Isometry3d grip = holderOnSwage(def);
  const double start = (-surfaceDeg - 30.0) * kAngleTestDeg;
  const double stop = (-surfaceDeg + 25.0) * kAngleTestDeg;

  Scene scene(def);
  int k = 0;
  for (int i = 0; i <= 10; ++i) scene.step(holderAt(def.needle->pose * grip, 0.1 * i, k++));
  const Eigen::Isometry3d first = needleOnPassCircle(g, start);
  for (int i = 1; i <= 50; ++i) {
    const double f = i / 50.0;
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = Eigen::Quaterniond(def.needle->pose.linear())
                        .slerp(f, Eigen::Quaterniond(first.linear()))
                        .toRotationMatrix();
    pose.translation() = (1.0 - f) * def.needle->pose.translation() + f * first.translation();
    scene.step(holderAt(pose * grip, 1.0, k++));
  }
  for (int i = 1; i <= 55; ++i)
    scene.step(holderAt(needleOnPassCircle(g, start + (stop - start) * i / 55.0) * grip, 1.0, k++));
  return scene.pierces();
}

class FlatWallPierceAngle : public ::testing::TestWithParam<double> {};

TEST_P(FlatWallPierceAngle, IsTheAngleTheNeedleMeetsTheWallAt) {
  const double surfaceDeg = GetParam();
  const std::vector<PierceEvent> pierces = turnThroughFlatWall(surfaceDeg);
  ASSERT_EQ(pierces.size(), 1u);
  // measured from the normal: 90° to the surface is 0°
  EXPECT_NEAR(pierces[0].angleDeg, 90.0 - surfaceDeg, 1.0);
  // where the circle meets z = 0
  EXPECT_NEAR(pierces[0].point.x(), -0.8 * std::sin(surfaceDeg * kAngleTestDeg), 0.01);
}

INSTANTIATE_TEST_SUITE_P(ToTheSurface, FlatWallPierceAngle, ::testing::Values(30.0, 45.0, 60.0, 90.0),
                         [](const ::testing::TestParamInfo<double>& info) {
                           return std::to_string(static_cast<int>(info.param)) + "deg";
                         });

TEST(PierceAngle, TheShippedWallDentedBeforeItsPunctureReadsThePassesGeometry) {
  SceneDefLoad load = loadSceneDef(std::string(MICROSIM_SOURCE_DIR) + "/resources/scenes/anastomosis.json");
  ASSERT_TRUE(std::holds_alternative<SceneDef>(load));
  const SceneDef def = std::get<SceneDef>(std::move(load));
  ASSERT_GT(def.needle->punctureForce, 0.0);
  const std::vector<ExpectedPierce> expected = stitchPierces(def);
  ASSERT_EQ(expected.size(), 4u);
  Scene scene(def);
  for (const InputFrame& f : scriptedStitch(def).frames) scene.step(f);
  ASSERT_EQ(scene.pierces().size(), 4u);

  // the entry into the near end's outer wall: the wall gave after the tip had turned some 6°
  // on along its curve, which the tip's own tangent would add
  EXPECT_NEAR(scene.pierces()[0].angleDeg, expected[0].angleDeg, 1.0);
  // and into the far end from its lumen, where the tip turning on would take some 6° off
  EXPECT_NEAR(scene.pierces()[2].angleDeg, expected[2].angleDeg, 1.0);
}

}  // namespace
}  // namespace microsim::sim
