// The draw list without GL: every shipped scene's tools and objects appear with the poses the
// engine gives them, the shadow pass draws exactly the lit list's casters, each forceps' tip
// marker sits where its jaws meet, and the contact cue comes on when the jaws straddle the
// wall, goes off in the air and gives way to the holding colour once they grasp.
#include "gui/render/draw_list.h"

#include "microsim/sim/scene/scene.h"
#include "microsim/sim/tools/forceps.h"
#include "microsim/sim/tools/microscissors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <variant>
#include <vector>

namespace microsim::gui {
namespace {

const std::string kDrawListScenes = std::string(MICROSIM_SOURCE_DIR) + "/resources/scenes";

bool sameMatrix(const QMatrix4x4& a, const QMatrix4x4& b, float tolerance = 1e-5f) {
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      if (std::abs(a(r, c) - b(r, c)) > tolerance) return false;
  return true;
}

QMatrix4x4 fromIsometry(const Eigen::Isometry3d& pose) { return toQMatrix(pose.matrix().cast<float>()); }

std::vector<const DrawItem*> itemsOf(const DrawList& list, DrawKind kind, int hand = -2) {
  std::vector<const DrawItem*> out;
  for (const DrawItem& i : list)
    if (i.kind == kind && (hand == -2 || i.hand == hand)) out.push_back(&i);
  return out;
}

sim::SceneDef loadDrawListScene(const std::string& path) {
  sim::SceneDefLoad load = sim::loadSceneDef(path);
  EXPECT_TRUE(std::holds_alternative<sim::SceneDef>(load)) << path;
  return std::get<sim::SceneDef>(std::move(load));
}

// a hand's tool at `position`, turned 30° about (1, 1, 0) so no transform is trivially the identity
sim::HandInput toolAt(sim::Instrument instrument, const Eigen::Vector3d& position, double closure) {
  sim::HandInput h;
  h.instrument = instrument;
  h.tracked = true;
  h.position = position;
  h.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.5236, Eigen::Vector3d(1, 1, 0).normalized()));
  h.closure = closure;
  return h;
}

// a hand's forceps pointing up (+x of the tool along the scene's +z), the jaws opening
// along the scene's y: from above they straddle whatever lies under the tip
sim::HandInput forcepsUpright(const Eigen::Vector3d& tip, double closure) {
  sim::HandInput h;
  h.instrument = sim::Instrument::Forceps;
  h.tracked = true;
  h.position = tip;
  Eigen::Matrix3d r;
  r.col(0) = Eigen::Vector3d::UnitZ();
  r.col(1) = Eigen::Vector3d::UnitY();
  r.col(2) = -Eigen::Vector3d::UnitX();
  h.orientation = Eigen::Quaterniond(r);
  h.closure = closure;
  return h;
}

MicroscopeCamera cameraOf(const sim::SceneDef& def) {
  MicroscopeCamera camera;
  camera.reset(def.camera);
  return camera;
}

TEST(DrawList, EveryToolAndObjectOfEachShippedSceneAppearsWhereTheEngineHasIt) {
  int scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kDrawListScenes)) {
    if (entry.path().extension() != ".json") continue;
    ++scenes;
    SCOPED_TRACE(entry.path().filename().string());
    const sim::SceneDef def = loadDrawListScene(entry.path().string());
    sim::Scene scene(def);

    // each hand takes its forceps, or the scalpel where the scene has one and no forceps for it
    sim::InputFrame frame;
    frame.time = scene.dt();
    std::array<bool, sim::kHandCount> scalpelIn{};
    for (int h = 0; h < sim::kHandCount; ++h) {
      const auto hs = static_cast<std::size_t>(h);
      const Eigen::Vector3d at(-2.0 + 4.0 * h, 1.0, 3.0);
      scalpelIn[hs] = !def.forceps[hs] && def.scalpel;
      frame.hands[hs] = toolAt(scalpelIn[hs] ? sim::Instrument::Scalpel : sim::Instrument::Forceps, at, 0.3);
    }
    scene.step(frame);
    sim::RenderSnapshot snapshot;
    sim::fillSnapshot(scene, snapshot);
    const DrawList list = buildDrawList(def, snapshot, cameraOf(def), {});

    // the drape and the tissue, in the scene frame
    ASSERT_EQ(itemsOf(list, DrawKind::Background).size(), 1u);
    ASSERT_EQ(itemsOf(list, DrawKind::Tissue).size(), 1u);
    EXPECT_TRUE(itemsOf(list, DrawKind::Tissue)[0]->model.isIdentity());
    EXPECT_EQ(itemsOf(list, DrawKind::Tissue)[0]->mesh, DrawMesh::Tissue);

    for (int h = 0; h < sim::kHandCount; ++h) {
      const auto hs = static_cast<std::size_t>(h);
      const Eigen::Isometry3d pose = Eigen::Translation3d(frame.hands[hs].position) * frame.hands[hs].orientation;
      const auto jaws = itemsOf(list, DrawKind::ForcepsJaw, h);
      const auto scalpel = itemsOf(list, DrawKind::Scalpel, h);
      const auto tip = itemsOf(list, DrawKind::TipMarker, h);
      if (def.forceps[hs]) {
        // both jaws, each at the engine's jaw pose for the pose and closure the hand gave
        const auto expected = sim::tools::jawPoses(*def.forceps[hs], pose, 0.3);
        ASSERT_EQ(jaws.size(), 2u) << "hand " << h;
        for (std::size_t j = 0; j < 2; ++j) {
          EXPECT_EQ(jaws[j]->mesh, jawMeshOf(static_cast<sim::Hand>(h)));
          EXPECT_TRUE(sameMatrix(jaws[j]->model, fromIsometry(expected[j]))) << "hand " << h << " jaw " << j;
        }
        // the tip marker where the jaws meet: the middle of the tips once closed
        ASSERT_EQ(tip.size(), 1u);
        const auto tips = sim::tools::jawTips(*def.forceps[hs], pose, 1.0);
        const Eigen::Vector3d meet = 0.5 * (tips[0] + tips[1]);
        const QVector3D drawn = tip[0]->model.map(QVector3D(0, 0, 0));
        EXPECT_NEAR(drawn.x(), meet.x(), 1e-5);
        EXPECT_NEAR(drawn.y(), meet.y(), 1e-5);
        EXPECT_NEAR(drawn.z(), meet.z(), 1e-5);
        EXPECT_TRUE(tip[0]->onTop);
      } else {
        EXPECT_TRUE(jaws.empty());
        EXPECT_TRUE(tip.empty());
      }
      if (scalpelIn[hs]) {
        ASSERT_EQ(scalpel.size(), 1u) << "hand " << h;
        EXPECT_EQ(scalpel[0]->mesh, DrawMesh::ScalpelBlade);
        EXPECT_TRUE(sameMatrix(scalpel[0]->model, fromIsometry(pose)));
      } else {
        EXPECT_TRUE(scalpel.empty());
      }
    }

    // the needle and the thread with a needle, in the scene frame
    const std::size_t suture = def.needle ? 1u : 0u;
    ASSERT_EQ(itemsOf(list, DrawKind::Needle).size(), suture);
    ASSERT_EQ(itemsOf(list, DrawKind::Thread).size(), suture);
    if (def.needle) {
      EXPECT_TRUE(itemsOf(list, DrawKind::Needle)[0]->model.isIdentity());
      EXPECT_TRUE(itemsOf(list, DrawKind::Thread)[0]->model.isIdentity());
    }
    EXPECT_TRUE(itemsOf(list, DrawKind::Scissors).empty());
  }
  EXPECT_GE(scenes, 6);
}

TEST(DrawList, AHandHoldingTheScalpelPutsItsForcepsDown) {
  const sim::SceneDef def = loadDrawListScene(kDrawListScenes + "/single_vessel.json");
  sim::Scene scene(def);
  sim::InputFrame frame;
  frame.time = scene.dt();
  frame.hands[0] = toolAt(sim::Instrument::Scalpel, Eigen::Vector3d(0.0, 0.0, 4.0), 0.0);
  scene.step(frame);
  sim::RenderSnapshot snapshot;
  sim::fillSnapshot(scene, snapshot);
  ASSERT_TRUE(snapshot.forceps[0].present);
  ASSERT_TRUE(snapshot.scalpels[0].present);
  const DrawList list = buildDrawList(def, snapshot, cameraOf(def), {});
  EXPECT_EQ(itemsOf(list, DrawKind::Scalpel, 0).size(), 1u);
  EXPECT_TRUE(itemsOf(list, DrawKind::ForcepsJaw, 0).empty());
  EXPECT_TRUE(itemsOf(list, DrawKind::TipMarker, 0).empty());
}

TEST(DrawList, TheScissorsInAHandAppearWithTheEnginesPoseAndOpeningAndOnlyThere) {
  const sim::SceneDef def = loadDrawListScene(kDrawListScenes + "/anastomosis.json");
  ASSERT_TRUE(def.scissors);
  sim::Scene scene(def);
  sim::InputFrame frame;
  frame.time = scene.dt();
  frame.hands[0] = toolAt(sim::Instrument::Forceps, Eigen::Vector3d(-2.0, 1.0, 3.0), 0.0);
  frame.hands[1] = toolAt(sim::Instrument::Scissors, Eigen::Vector3d(1.5, 1.0, 3.0), 0.4);
  scene.step(frame);
  sim::RenderSnapshot snapshot;
  sim::fillSnapshot(scene, snapshot);
  ASSERT_TRUE(snapshot.scissors[1].present);
  const DrawList list = buildDrawList(def, snapshot, cameraOf(def), {});

  // the right hand: two blades at the engine's blade poses for this opening, the shaft at the
  // tool's pose; its forceps is put down
  const Eigen::Isometry3d pose = Eigen::Translation3d(frame.hands[1].position) * frame.hands[1].orientation;
  const auto blades = sim::tools::scissorsBladePoses(*def.scissors, pose, 0.4);
  const auto scissors = itemsOf(list, DrawKind::Scissors, 1);
  ASSERT_EQ(scissors.size(), 3u);
  for (std::size_t b = 0; b < 2; ++b) {
    EXPECT_EQ(scissors[b]->mesh, DrawMesh::ScissorsBlade);
    EXPECT_TRUE(sameMatrix(scissors[b]->model, fromIsometry(blades[b]))) << "blade " << b;
    EXPECT_TRUE(scissors[b]->castsShadow);
  }
  EXPECT_EQ(scissors[2]->mesh, DrawMesh::ScissorsShaft);
  EXPECT_TRUE(sameMatrix(scissors[2]->model, fromIsometry(pose)));
  EXPECT_TRUE(itemsOf(list, DrawKind::ForcepsJaw, 1).empty());
  EXPECT_TRUE(itemsOf(list, DrawKind::TipMarker, 1).empty());
  // the blade tips drawn where the engine has them: open by the closure's angle
  const auto tips = sim::tools::scissorsBladeTips(*def.scissors, 0.4);
  for (std::size_t b = 0; b < 2; ++b) {
    const QVector3D drawn = scissors[b]->model.map(QVector3D(0, 0, 0));
    const Eigen::Vector3d engine = pose * tips[b];
    EXPECT_NEAR(drawn.x(), engine.x(), 1e-5);
    EXPECT_NEAR(drawn.y(), engine.y(), 1e-5);
    EXPECT_NEAR(drawn.z(), engine.z(), 1e-5);
  }
  // the left hand holds its forceps: no scissors there, its jaws are drawn
  EXPECT_TRUE(itemsOf(list, DrawKind::Scissors, 0).empty());
  EXPECT_EQ(itemsOf(list, DrawKind::ForcepsJaw, 0).size(), 2u);

  // the scissors put down: gone, the forceps back
  frame.time += scene.dt();
  frame.hands[1].instrument = sim::Instrument::Forceps;
  scene.step(frame);
  sim::fillSnapshot(scene, snapshot);
  const DrawList back = buildDrawList(def, snapshot, cameraOf(def), {});
  EXPECT_TRUE(itemsOf(back, DrawKind::Scissors).empty());
  EXPECT_EQ(itemsOf(back, DrawKind::ForcepsJaw, 1).size(), 2u);
}

TEST(DrawList, TheShadowPassDrawsTheLitListsCastersAndNothingElse) {
  const sim::SceneDef def = loadDrawListScene(kDrawListScenes + "/anastomosis.json");
  sim::Scene scene(def);
  sim::RenderSnapshot snapshot;
  sim::fillSnapshot(scene, snapshot);
  Guide ring;
  ring.point = Eigen::Vector3d(0.0, 1.0, 0.5);
  const DrawList list = buildDrawList(def, snapshot, cameraOf(def), {ring});
  const DrawList casters = shadowCasters(list);

  // the same items in the same order, with the same transforms
  std::vector<const DrawItem*> expected;
  for (const DrawItem& i : list)
    if (i.castsShadow) expected.push_back(&i);
  ASSERT_EQ(casters.size(), expected.size());
  for (std::size_t k = 0; k < casters.size(); ++k) {
    EXPECT_EQ(casters[k].kind, expected[k]->kind);
    EXPECT_EQ(casters[k].mesh, expected[k]->mesh);
    EXPECT_TRUE(sameMatrix(casters[k].model, expected[k]->model));
  }
  // matter casts a shadow (tissue, four jaws, needle, thread), marks and the drape do not
  EXPECT_EQ(casters.size(), 7u);
  for (const DrawItem& i : list) {
    const bool matter = i.kind == DrawKind::Tissue || i.kind == DrawKind::ForcepsJaw || i.kind == DrawKind::Scalpel ||
                        i.kind == DrawKind::Scissors ||
                        i.kind == DrawKind::Needle || i.kind == DrawKind::Thread;
    EXPECT_EQ(i.castsShadow, matter) << static_cast<int>(i.kind);
    EXPECT_EQ(i.onTop, i.kind == DrawKind::TipMarker || i.kind == DrawKind::ContactCue || i.kind == DrawKind::Guide);
  }
  // marks come last, so the viewport draws them over the scene in one go
  bool marks = false;
  for (const DrawItem& i : list) {
    if (marks) {
      EXPECT_TRUE(i.onTop);
    }
    marks = marks || i.onTop;
  }
}

TEST(DrawList, GuidesAreRingsAndArrowsAtTheirPoints) {
  const sim::SceneDef def = loadDrawListScene(kDrawListScenes + "/anastomosis.json");
  sim::Scene scene(def);
  sim::RenderSnapshot snapshot;
  sim::fillSnapshot(scene, snapshot);
  Guide ring;
  ring.point = Eigen::Vector3d(0.0, 2.0, 0.5);
  ring.direction = Eigen::Vector3d::UnitX();
  ring.size = 0.3;
  Guide arrow;
  arrow.kind = Guide::Kind::NeedleDirection;
  arrow.point = Eigen::Vector3d(-2.0, -2.0, 0.5);
  arrow.direction = Eigen::Vector3d::UnitY();
  arrow.size = 1.0;
  arrow.done = true;
  const DrawList list = buildDrawList(def, snapshot, cameraOf(def), {ring, arrow});
  const auto guides = itemsOf(list, DrawKind::Guide);
  ASSERT_EQ(guides.size(), 2u);
  EXPECT_EQ(guides[0]->mesh, DrawMesh::Ring);
  EXPECT_EQ(guides[1]->mesh, DrawMesh::Arrow);
  // the ring's unit circle lands at its radius around the point, in the plane normal to x
  const QVector3D onRing = guides[0]->model.map(QVector3D(1, 0, 0));
  EXPECT_NEAR((onRing - QVector3D(0.0f, 2.0f, 0.5f)).length(), 0.3f, 1e-5f);
  EXPECT_NEAR(onRing.x(), 0.0f, 1e-5f);
  // the arrow's point at its length along its direction
  const QVector3D point = guides[1]->model.map(QVector3D(0, 0, 1));
  EXPECT_NEAR((point - QVector3D(-2.0f, -1.0f, 0.5f)).length(), 0.0f, 1e-5f);
  // a guide that is done is dimmed
  EXPECT_NE(guides[0]->material.colour, guides[1]->material.colour);
}

TEST(DrawList, TheContactCueComesOnWhenTheJawsStraddleTheWall) {
  const sim::SceneDef def = loadDrawListScene(kDrawListScenes + "/anastomosis.json");
  sim::Scene scene(def);
  const MicroscopeCamera camera = cameraOf(def);
  sim::RenderSnapshot snapshot;
  const auto stepWith = [&](const Eigen::Vector3d& tip, double closure) {
    sim::InputFrame frame;
    frame.time = scene.time() + scene.dt();
    frame.hands[1] = forcepsUpright(tip, closure);
    scene.step(frame);
    sim::fillSnapshot(scene, snapshot);
    return buildDrawList(def, snapshot, camera, {});
  };

  // high above the wall: nothing between the jaws, the marker idle
  DrawList list = stepWith(Eigen::Vector3d(-1.5, 0.0, 2.5), 0.0);
  EXPECT_EQ(snapshot.forceps[1].between, sim::JawTarget::Nothing);
  EXPECT_TRUE(itemsOf(list, DrawKind::ContactCue, 1).empty());
  ASSERT_EQ(itemsOf(list, DrawKind::TipMarker, 1).size(), 1u);
  EXPECT_EQ(itemsOf(list, DrawKind::TipMarker, 1)[0]->material.colour, kTipIdle);

  // the open jaws' tip just into the top of the wall (outer radius 0.5 mm): the wall is
  // between them, the marker turns and a ring shows where they would take it
  list = stepWith(Eigen::Vector3d(-1.5, 0.0, 0.45), 0.0);
  EXPECT_EQ(snapshot.forceps[1].between, sim::JawTarget::Tissue);
  const auto cue = itemsOf(list, DrawKind::ContactCue, 1);
  ASSERT_EQ(cue.size(), 1u);
  const QVector3D at = cue[0]->model.map(QVector3D(0, 0, 0));
  EXPECT_NEAR(at.x(), -1.5f, 0.15f);
  EXPECT_NEAR(at.y(), 0.0f, 0.15f);
  EXPECT_NEAR(at.z(), 0.5f, 0.1f);
  EXPECT_EQ(itemsOf(list, DrawKind::TipMarker, 1)[0]->material.colour, kTipContact);
  // the ring faces the microscope and the side view alike (45° to each): a ring in both
  const QVector3D normal = (cue[0]->model.map(QVector3D(0, 0, 1)) - at).normalized();
  EXPECT_NEAR(QVector3D::dotProduct(normal, -camera.forward()), std::sqrt(0.5f), 1e-4f);
  EXPECT_NEAR(QVector3D::dotProduct(normal, -camera.up()), std::sqrt(0.5f), 1e-4f);

  // closed there: the jaws hold the wall, the ring gives way to the holding colour
  list = stepWith(Eigen::Vector3d(-1.5, 0.0, 0.45), 1.0);
  ASSERT_TRUE(snapshot.forceps[1].holdsTissue);
  EXPECT_TRUE(itemsOf(list, DrawKind::ContactCue, 1).empty());
  EXPECT_EQ(itemsOf(list, DrawKind::TipMarker, 1)[0]->material.colour, kTipHolding);
}

}  // namespace
}  // namespace microsim::gui
