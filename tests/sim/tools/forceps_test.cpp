#include "microsim/sim/tools/forceps.h"

#include "microsim/sim/scene/scene.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <variant>

namespace microsim::sim {
namespace {

const std::string kForcepsMeshes = std::string(MICROSIM_SOURCE_DIR) + "/resources/meshes";

ForcepsDef jawDef() {
  ForcepsDef def;
  def.jawVertices.resize(3, 3);
  def.jawVertices << 0, 3, 3, 0, 0, 0.1, 0, 0.1, 0;
  def.jawTriangles = {{0, 1, 2}};
  def.openingDeg = 20.0;
  return def;
}

TEST(Forceps, JawTipsMeetWhenClosedAndOpenBySymmetricAngles) {
  const ForcepsDef def = jawDef();
  EXPECT_DOUBLE_EQ(tools::jawLength(def), 3.0);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Vec3(1, 2, 3);
  const auto closed = tools::jawTips(def, pose, 1.0);
  EXPECT_LT((closed[0] - Vec3(1, 2, 3)).norm(), 1e-15);
  EXPECT_LT((closed[1] - Vec3(1, 2, 3)).norm(), 1e-15);
  const auto open = tools::jawTips(def, pose, 0.0);
  const double t = 20.0 * std::numbers::pi / 180.0;
  EXPECT_LT((open[0] - Vec3(1 + 3 - 3 * std::cos(t), 2 + 3 * std::sin(t), 3)).norm(), 1e-12);
  EXPECT_LT((open[1] - Vec3(1 + 3 - 3 * std::cos(t), 2 - 3 * std::sin(t), 3)).norm(), 1e-12);
  // the lower jaw is the mirror image, wound the other way
  const Points v = tools::jawVertices(def, pose, 0.0);
  EXPECT_NEAR(v(1, 5) - 2.0, -(v(1, 2) - 2.0), 1e-12);
  EXPECT_EQ(tools::jawTriangles(def).back(), (std::array<int, 3>{3, 5, 4}));
}

// A hand that lets go drops the hold at once, but the jaws' spring parts them at its own
// speed: from closed to open in openingSeconds, however far the hand's closure jumped. Closing
// follows the hand at once.
TEST(Forceps, JawsOpenNoFasterThanTheirSpringButLetGoAtOnce) {
  ForcepsDef def = jawDef();
  def.openingSeconds = 0.1;
  tools::Forceps forceps(def);
  const Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  const double dt = 0.01;
  bool released = false;
  EXPECT_TRUE(forceps.update(pose, 1.0, dt, released))
      << "closed from open in one step: time to grab";
  EXPECT_DOUBLE_EQ(forceps.closure(), 1.0);
  EXPECT_FALSE(released);

  EXPECT_FALSE(forceps.update(pose, 0.0, dt, released));
  EXPECT_TRUE(released) << "the hold goes with the hand's squeeze";
  EXPECT_FALSE(forceps.closed());
  EXPECT_NEAR(forceps.closure(), 0.9, 1e-12)
      << "a tenth of the way open after a tenth of the opening time";
  for (int k = 2; k <= 10; ++k) {
    forceps.update(pose, 0.0, dt, released);
    EXPECT_FALSE(released);
    EXPECT_NEAR(forceps.closure(), 1.0 - 0.1 * k, 1e-12) << k;
  }
  forceps.update(pose, 0.0, dt, released);
  EXPECT_DOUBLE_EQ(forceps.closure(), 0.0) << "fully open, and no further";

  // half open on the way: a squeeze closes them at once; a hand easing to 0.7 is followed
  // as fast as the spring allows
  forceps.update(pose, 1.0, dt, released);
  forceps.update(pose, 0.7, dt, released);
  EXPECT_TRUE(released);
  EXPECT_NEAR(forceps.closure(), 0.9, 1e-12);
  forceps.update(pose, 0.7, dt, released);
  forceps.update(pose, 0.7, dt, released);
  EXPECT_NEAR(forceps.closure(), 0.7, 1e-12);
}

// a 4 by 4 grid of 2 mm cells in z = 0 (nodes at −4, −2, .., 4 mm), its border fixed, and
// the right forceps with the shipped jaws
SceneDef forcepsGridScene(const std::string& solver) {
  const std::string text = R"({"objects": [{"type": "grid", "cells": [4, 4], "size": 2, "stiffness": 1000,
      "fix_border": true}],
    "solver": {"name": ")" + solver + R"(", "iterations": 50, "tolerance": 1e-10},
    "tools": {"forceps": [{"hand": "right", "mesh": "forceps_jaw.obj"}]}})";
  SceneDefLoad load = parseSceneDef(text, "grab.json", kForcepsMeshes);
  EXPECT_TRUE(std::holds_alternative<SceneDef>(load));
  return std::get<SceneDef>(std::move(load));
}

// jaws pointing down (tool +x, tips → hinge, along scene +z), opening along scene y
const Eigen::Quaterniond kForcepsFromAbove(Eigen::AngleAxisd(-0.5 * std::numbers::pi, Vec3::UnitY()));

InputFrame forcepsAt(const Vec3& tip, double closure, int k,
                     const Eigen::Quaterniond& orientation = kForcepsFromAbove) {
  InputFrame f;
  f.time = 0.01 * k;
  f.hand(Hand::Left).instrument = Instrument::None;
  HandInput& h = f.hand(Hand::Right);
  h.instrument = Instrument::Forceps;
  h.tracked = true;
  h.position = tip;
  h.orientation = orientation;
  h.closure = closure;
  return f;
}

InputFrame forcepsAt(const Eigen::Isometry3d& pose, double closure, int k) {
  return forcepsAt(pose.translation(), closure, k, Eigen::Quaterniond(pose.linear()));
}

// the grid face with corners (−2, −2), (0, −2), (0, 0) and its centroid, 0.94 mm from the
// nearest node
constexpr double kFaceCentroidX = -2.0 / 3.0;
constexpr double kFaceCentroidY = -4.0 / 3.0;

Vec3 forcepsFacePoint(const Scene& scene, const tools::HeldFacePoint& p) {
  Vec3 point = Vec3::Zero();
  for (std::size_t c = 0; c < 3; ++c)
    point += p.barycentric[static_cast<Eigen::Index>(c)] * scene.tissueState().x.col(p.corners[c]);
  return point;
}

// The open jaws pressed 0.02 mm through the sheet, their tips standing above it over the middle
// of one face, then closed: the face is held at the middle of what they closed on, and the
// sheet follows the lifted jaws there; opened, the sheet springs back.
TEST(Forceps, AJawClosingOnTheMiddleOfAFaceHoldsItAndAPullMovesTheFace) {
  Scene scene(forcepsGridScene("newton"));
  const Vec3 centroid(kFaceCentroidX, kFaceCentroidY, 0.0);
  const Vec3 tip = centroid - Vec3(0, 0, 0.02);
  int k = 0;
  scene.step(forcepsAt(tip, 0.0, k++));
  scene.step(forcepsAt(tip, 1.0, k++));
  const tools::Forceps& forceps = *scene.forceps(Hand::Right);
  ASSERT_EQ(forceps.heldFaces().size(), 1u);
  const tools::HeldFacePoint held = forceps.heldFaces().front();
  std::vector<Vec3> corners;
  for (int c : held.corners) corners.push_back(scene.tissue().restPositions().col(c));
  EXPECT_TRUE(std::find(corners.begin(), corners.end(), Vec3(-2, -2, 0)) != corners.end());
  EXPECT_TRUE(std::find(corners.begin(), corners.end(), Vec3(0, -2, 0)) != corners.end());
  EXPECT_TRUE(std::find(corners.begin(), corners.end(), Vec3(0, 0, 0)) != corners.end());
  EXPECT_LT((forcepsFacePoint(scene, held) - centroid).norm(), 1e-12);
  EXPECT_DOUBLE_EQ(held.share, 1.0);
  ASSERT_FALSE(scene.events().empty());
  EXPECT_EQ(scene.events().back().kind, SceneEventKind::GrabTissue);
  EXPECT_EQ(scene.events().back().hand, static_cast<int>(Hand::Right));
  EXPECT_EQ(scene.events().back().count, 3);  // the face's corners, all free
  EXPECT_EQ(forceps.heldNodes().size(), 3u);

  // lifted 0.5 mm: the face's point follows the jaws, its corners rise with it; the hold is a
  // point spring (newton takes them), no node is forced
  for (int s = 1; s <= 10; ++s) scene.step(forcepsAt(tip + Vec3(0, 0, 0.05 * s), 1.0, k++));
  const Vec3 target = forceps.pose() * held.offset;
  EXPECT_LT((target - (centroid + Vec3(0, 0, 0.5))).norm(), 1e-12);
  EXPECT_LT((forcepsFacePoint(scene, held) - target).norm(), 2e-3);
  for (int c : held.corners) EXPECT_GT(scene.tissueState().x(2, c), 0.2);
  EXPECT_EQ(scene.controls().size(), 0);
  EXPECT_EQ(scene.controls().springs.size(), 1u);

  // opened (and lifted clear of the sheet): released, and the sheet springs back
  scene.step(forcepsAt(tip + Vec3(0, 0, 2.0), 0.0, k++));
  EXPECT_EQ(scene.events().back().kind, SceneEventKind::ReleaseTissue);
  EXPECT_TRUE(forceps.heldFaces().empty());
  EXPECT_TRUE(forceps.heldNodes().empty());
  EXPECT_TRUE(scene.controls().springs.empty());
  for (int s = 0; s < 5; ++s) scene.step(forcepsAt(tip + Vec3(0, 0, 2.0), 0.0, k++));
  // (back on the plane: a sheet of links has no bending stiffness, its last micrometres are slow)
  EXPECT_LT((forcepsFacePoint(scene, held) - centroid).norm(), 1e-3);
}

// A solver without point springs (the paper's peers) holds the same face by its corners.
TEST(Forceps, WithoutPointSpringsTheHeldFacesCornersFollowTheJaws) {
  Scene scene(forcepsGridScene("implicit"));
  const Vec3 tip(kFaceCentroidX, kFaceCentroidY, -0.02);
  int k = 0;
  scene.step(forcepsAt(tip, 0.0, k++));
  scene.step(forcepsAt(tip, 1.0, k++));
  const tools::Forceps& forceps = *scene.forceps(Hand::Right);
  ASSERT_EQ(forceps.heldFaces().size(), 1u);
  ASSERT_EQ(forceps.heldNodes().size(), 3u);
  std::vector<Vec3> taken;
  for (int n : forceps.heldNodes()) taken.push_back(scene.tissueState().x.col(n));
  for (int s = 1; s <= 5; ++s) scene.step(forcepsAt(tip + Vec3(0, 0, 0.05 * s), 1.0, k++));
  EXPECT_EQ(scene.controls().size(), 3);
  EXPECT_TRUE(scene.controls().springs.empty());
  for (std::size_t i = 0; i < taken.size(); ++i)
    EXPECT_LT((scene.tissueState().x.col(forceps.heldNodes()[i]) - (taken[i] + Vec3(0, 0, 0.25))).norm(), 1e-12);
}

TEST(Forceps, AJawClosingOnEmptySpaceHoldsNothingAndSaysSo) {
  Scene scene(forcepsGridScene("newton"));
  // above the sheet: the closing jaws meet nothing
  scene.step(forcepsAt(Vec3(0.5, 0.5, 0.3), 0.0, 0));
  scene.step(forcepsAt(Vec3(0.5, 0.5, 0.3), 1.0, 1));
  const tools::Forceps& forceps = *scene.forceps(Hand::Right);
  EXPECT_TRUE(forceps.heldFaces().empty());
  EXPECT_TRUE(forceps.heldNodes().empty());
  EXPECT_FALSE(forceps.holdsSuture());
  ASSERT_EQ(scene.events().size(), 1u);
  EXPECT_EQ(scene.events().back().kind, SceneEventKind::GraspEmpty);
  EXPECT_EQ(scene.events().back().hand, static_cast<int>(Hand::Right));
  // already closed when it reaches the sheet: no grasp, no new event
  scene.step(forcepsAt(Vec3(kFaceCentroidX, kFaceCentroidY, -0.02), 1.0, 2));
  EXPECT_TRUE(forceps.heldFaces().empty());
  EXPECT_EQ(scene.events().size(), 1u);
  // a needle holder takes no tissue: it closes on nothing
  InputFrame open = forcepsAt(Vec3(kFaceCentroidX, kFaceCentroidY, -0.02), 0.0, 3);
  open.hand(Hand::Right).instrument = Instrument::NeedleHolder;
  scene.step(open);
  InputFrame closed = open;
  closed.time = 0.04;
  closed.hand(Hand::Right).closure = 1.0;
  scene.step(closed);
  EXPECT_TRUE(forceps.heldFaces().empty());
  EXPECT_EQ(scene.events().back().kind, SceneEventKind::GraspEmpty);
}

// The shipped anastomosis's wall, grasped from above near end 0's cut and lifted 0.5 mm (lesson
// 1 asks for 0.3): the held points follow the jaws within a fraction of the 0.1 mm wall. The
// lag is the hold's stretch, F / k shared by area: it measures ForcepsDef::holdStiffness
// (forceps.h). A face the jaws only clip a sliver of carries a small share and lags most.
TEST(Forceps, ShippedHoldFollowsTheJawWithinAFractionOfTheWall) {
  SceneDefLoad load = loadSceneDef(std::string(MICROSIM_SOURCE_DIR) + "/resources/scenes/anastomosis.json");
  ASSERT_TRUE(std::holds_alternative<SceneDef>(load));
  Scene scene(std::get<SceneDef>(std::move(load)));
  const SceneVessel& end0 = scene.def().vessels.front();
  const Vec3 top = end0.def.origin + 0.8 * end0.def.length * end0.def.direction + Vec3(0, 0, end0.def.radius - 0.03);
  int k = 0;
  const auto at = [&](const Vec3& tip, double closure) { scene.step(forcepsAt(tip, closure, k++)); };
  at(top, 0.0);
  at(top, 1.0);
  const tools::Forceps& forceps = *scene.forceps(Hand::Right);
  ASSERT_FALSE(forceps.heldFaces().empty());
  // the largest lag of a held point and the lag of the held patch as a whole (by share)
  const auto lags = [&] {
    double largest = 0.0, patch = 0.0;
    for (const tools::HeldFacePoint& p : forceps.heldFaces()) {
      Vec3 point = Vec3::Zero();
      for (std::size_t c = 0; c < 3; ++c)
        point += p.barycentric[static_cast<Eigen::Index>(c)] * scene.tissueState().x.col(p.corners[c]);
      const double lag = (point - forceps.pose() * p.offset).norm();
      largest = std::max(largest, lag);
      patch += p.share * lag;
    }
    return std::pair<double, double>{largest, patch};
  };
  for (int s = 1; s <= 6; ++s) at(top + Vec3(0, 0, 0.05 * s), 1.0);
  const auto [lessonLargest, lessonPatch] = lags();
  for (int s = 7; s <= 15; ++s) at(top + Vec3(0, 0, 0.05 * std::min(s, 10)), 1.0);
  const auto [largest, patch] = lags();
  const double lifted = (scene.tissueState().x - scene.tissue().restPositions()).colwise().norm().maxCoeff();
  EXPECT_GT(lifted, 0.45);
  EXPECT_LT(lessonPatch, 0.003);
  EXPECT_LT(lessonLargest, 0.01);
  EXPECT_LT(patch, 0.005);
  EXPECT_LT(largest, 0.02);
  RecordProperty("hold_lag_at_0_3mm", std::to_string(lessonPatch) + " (largest " + std::to_string(lessonLargest) + ")");
  RecordProperty("hold_lag_at_0_5mm", std::to_string(patch) + " (largest " + std::to_string(largest) + ")");
  RecordProperty("held_faces", std::to_string(forceps.heldFaces().size()));
}

// a small lattice out of the way and a curved 0.8 mm needle (8 links) with 8 mm of thread
// (52 links), laid out in its frame's xy plane at (10, 0, 0)
SceneDef forcepsNeedleScene() {
  const std::string text = R"({"objects": [{"type": "lattice", "size": [2, 2, 2]}],
    "solver": {"name": "newton", "iterations": 20, "tolerance": 1e-8},
    "tools": {"forceps": [{"hand": "right", "mesh": "forceps_jaw.obj"}],
      "needle": {"shape": "curved", "radius": 0.8, "needle_links": 8, "links": 60, "thread_length": 8.0,
                 "position": [10, 0, 0], "rotation": [1, 0, 0, 0], "solver": "direct"}}})";
  SceneDefLoad load = parseSceneDef(text, "needle.json", kForcepsMeshes);
  EXPECT_TRUE(std::holds_alternative<SceneDef>(load));
  return std::get<SceneDef>(std::move(load));
}

// the needle scene after one idle step: its suture and the next frame's number
struct ForcepsSutureRig {
  Scene scene{forcepsNeedleScene()};
  const suture::SutureModel& model = *scene.sutureModel();
  const Points& x = scene.sutureState()->x;
  int k = 1;
  ForcepsSutureRig() { scene.step(InputFrame{}); }
};

// Jaws across the suture at the point `fraction` along link `link` of x: tool +x along
// `across` (unit, normal to the link), the link along the jaws' width (tool z), the point
// 0.5 mm from the tips on the line where the jaws meet.
Eigen::Isometry3d forcepsAcross(const Points& x, int link, double fraction, const Vec3& across) {
  const Vec3 point = (1.0 - fraction) * x.col(link) + fraction * x.col(link + 1);
  const Vec3 along = (x.col(link + 1) - x.col(link)).normalized();
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear().col(0) = across;
  pose.linear().col(1) = along.cross(across);
  pose.linear().col(2) = along;
  pose.translation() = point - 0.5 * across;
  return pose;
}

// The pose `s` steps along a path that turns and shifts the tool.
Eigen::Isometry3d forcepsMoved(const Eigen::Isometry3d& from, int s) {
  Eigen::Isometry3d pose = from;
  pose.translation() += Vec3(0.02, -0.01, 0.015) * s;
  pose.linear() = Eigen::AngleAxisd(0.02 * s, Vec3(1.0, 2.0, -1.0).normalized()).toRotationMatrix() * from.linear();
  return pose;
}

// The needle taken between two of its nodes is held there: it moves rigidly with the jaws, the
// point it was taken at stays where the jaws hold it and so does its angle on them; opened and
// closed again at another point and angle, it is held there.
TEST(Forceps, AJawClosingOnTheNeedleBetweenNodesHoldsItAtThatPointAndAngle) {
  ForcepsSutureRig rig;
  // named references, not a structured binding: lambdas below capture them (clang 14)
  Scene& scene = rig.scene;
  const suture::SutureModel& model = rig.model;
  const Points& x = rig.x;
  int& k = rig.k;
  Eigen::Isometry3d away = Eigen::Isometry3d::Identity();
  away.translation() = Vec3(20, 20, 20);
  const auto graspAndCarry = [&](int link, double fraction, const auto& across) {
    // open out of the way, then closed at the point on the needle as it lies now (the grasp
    // reads the suture as the last step left it)
    scene.step(forcepsAt(away, 0.0, k++));
    const Eigen::Isometry3d grasp = forcepsAcross(x, link, fraction, across());
    scene.step(forcepsAt(grasp, 1.0, k++));
    const tools::Forceps& forceps = *scene.forceps(Hand::Right);
    ASSERT_TRUE(forceps.holdsSuture());
    EXPECT_EQ(forceps.heldSutureNode(), link);
    EXPECT_NEAR(forceps.heldSutureFraction(), fraction, 1e-9);
    EXPECT_EQ(scene.events().back().kind, SceneEventKind::GripSuture);
    EXPECT_EQ(scene.events().back().index, link);
    const auto point = [&] { return Vec3((1.0 - fraction) * x.col(link) + fraction * x.col(link + 1)); };
    const Vec3 inJaws = grasp.inverse() * point();
    const Eigen::Matrix3d onJaws = grasp.linear().transpose() * suture::needleRotation(model, x);
    EXPECT_LT(inJaws.norm() - 0.5, 1e-9);
    for (int s = 1; s <= 20; ++s) {
      const Eigen::Isometry3d pose = forcepsMoved(grasp, s);
      scene.step(forcepsAt(pose, 1.0, k++));
      SCOPED_TRACE(s);
      EXPECT_LT((point() - pose * inJaws).norm(), 1e-9);
      EXPECT_LT((suture::needleRotation(model, x) - pose.linear() * onJaws).norm(), 1e-9);
      for (int i = 0; i < model.swage(); ++i)
        EXPECT_NEAR((x.col(i + 1) - x.col(i)).norm(), model.rest(i), 1e-9);
    }
    // let go, and wait for the needle to come to rest (the drag)
    scene.step(forcepsAt(forcepsMoved(grasp, 20), 0.0, k++));
    EXPECT_EQ(scene.events().back().kind, SceneEventKind::ReleaseSuture);
    EXPECT_FALSE(scene.forceps(Hand::Right)->holdsSuture());
  };
  // across the needle's plane, 0.4 along link 3; then, wherever it was let go, 0.7 along
  // link 6 with the jaws turned 0.5 rad out of the plane's normal
  graspAndCarry(3, 0.4, [] { return Vec3::UnitZ(); });
  graspAndCarry(6, 0.7, [&] {
    const Vec3 along = (x.col(7) - x.col(6)).normalized();
    const Vec3 normal = along.cross(x.col(5) - x.col(6)).normalized();
    return Vec3(std::cos(0.5) * normal + std::sin(0.5) * normal.cross(along));
  });
}

// The thread taken between two nodes: the point follows the jaws and its link keeps its
// direction in them (clamped), at its length.
TEST(Forceps, AJawClosingOnTheThreadBetweenNodesHoldsItThere) {
  ForcepsSutureRig rig;
  // named references, not a structured binding: lambdas below capture them (clang 14)
  Scene& scene = rig.scene;
  const suture::SutureModel& model = rig.model;
  const Points& x = rig.x;
  int& k = rig.k;
  const int link = 20;
  const double fraction = 0.5;
  ASSERT_GT(link, model.swage());
  const Eigen::Isometry3d grasp = forcepsAcross(x, link, fraction, Vec3::UnitZ());
  scene.step(forcepsAt(grasp, 0.0, k++));
  scene.step(forcepsAt(grasp, 1.0, k++));
  const tools::Forceps& forceps = *scene.forceps(Hand::Right);
  ASSERT_TRUE(forceps.holdsSuture());
  EXPECT_EQ(forceps.heldSutureNode(), link);
  EXPECT_NEAR(forceps.heldSutureFraction(), fraction, 1e-9);
  const auto grip = forceps.grip();
  ASSERT_TRUE(grip.has_value());
  EXPECT_FALSE(suture::gripHoldsNeedle(model, *grip));
  const Vec3 inJaws = grasp.inverse() * suture::gripPoint(x, *grip);
  const Vec3 direction = grasp.linear().transpose() * (x.col(link + 1) - x.col(link)).normalized();
  for (int s = 1; s <= 20; ++s) {
    const Eigen::Isometry3d pose = forcepsMoved(grasp, s);
    scene.step(forcepsAt(pose, 1.0, k++));
    SCOPED_TRACE(s);
    EXPECT_LT((suture::gripPoint(x, *grip) - pose * inJaws).norm(), 1e-9);
    EXPECT_LT(((x.col(link + 1) - x.col(link)) - model.rest(link) * (pose.linear() * direction)).norm(), 1e-9);
  }
  // the rest of the chain follows at its lengths
  EXPECT_LT(suture::maxAbsStretch(model, x, scene.sutureState()->alive), 1e-6);
}

TEST(Forceps, RejectedInputIsReportedAndTheLastGoodFrameIsUsed) {
  Scene scene(forcepsGridScene("newton"));
  const Vec3 tip(kFaceCentroidX, kFaceCentroidY, -0.02);
  scene.step(forcepsAt(tip, 0.0, 0));
  scene.step(forcepsAt(tip, 1.0, 1));
  InputFrame bad = forcepsAt(Vec3(tip.x(), tip.y(), std::nan("")), 1.0, 2);
  const StepReport r = scene.step(bad);
  EXPECT_TRUE(r.inputRejected);
  EXPECT_EQ(scene.events().back().kind, SceneEventKind::InputRejected);
  EXPECT_EQ(scene.events().back().rejection, InputRejection::NonFinite);
  EXPECT_EQ(scene.forceps(Hand::Right)->heldFaces().size(), 1u);
  EXPECT_TRUE(scene.tissueState().x.allFinite());
  InputFrame back = forcepsAt(tip, 1.0, 0);  // time going backwards
  scene.step(back);
  EXPECT_EQ(scene.events().back().rejection, InputRejection::TimeBackwards);
}

}  // namespace
}  // namespace microsim::sim
