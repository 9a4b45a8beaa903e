#include "microsim/sim/tools/scalpel.h"

#include "microsim/sim/scene/scene.h"

#include <gtest/gtest.h>

#include <numbers>
#include <string>
#include <variant>
#include <vector>

namespace microsim::sim {
namespace {

const std::string kScalpelScenes = std::string(MICROSIM_SOURCE_DIR) + "/resources/scenes/";

// connected pieces of the tissue through its alive links
int components(const SpringModel& m) {
  std::vector<int> piece(static_cast<std::size_t>(m.nodeCount()), -1);
  int count = 0;
  for (int s = 0; s < m.nodeCount(); ++s) {
    if (piece[static_cast<std::size_t>(s)] >= 0) continue;
    std::vector<int> stack{s};
    piece[static_cast<std::size_t>(s)] = count;
    while (!stack.empty()) {
      const int i = stack.back();
      stack.pop_back();
      for (int l : m.linksOf(i)) {
        const int j = m.otherEnd(l, i);
        if (m.link(l).alive && piece[static_cast<std::size_t>(j)] < 0) {
          piece[static_cast<std::size_t>(j)] = count;
          stack.push_back(j);
        }
      }
    }
    ++count;
  }
  return count;
}

InputFrame bladeAt(const Vec3& tip, int k) {
  InputFrame f;
  f.time = 0.01 * k;
  HandInput& h = f.hand(Hand::Left);
  h.instrument = Instrument::Scalpel;
  h.tracked = true;
  h.position = tip;
  // edge along +y, blade face normal along x, height up +z
  h.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(std::numbers::pi / 2, Vec3::UnitZ()));
  f.hand(Hand::Right).instrument = Instrument::None;
  return f;
}

TEST(Scalpel, BladeCornersFollowThePose) {
  ScalpelDef def;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Vec3(1, 0, 0);
  const Points c = tools::bladeCorners(def, pose);
  EXPECT_EQ(c.col(0), Vec3(1, 0, 0));
  EXPECT_EQ(c.col(1), Vec3(3, 0, 0));
  EXPECT_EQ(c.col(2), Vec3(3, 0, 0.5));
}

TEST(Scalpel, CuttingAcrossAVesselSeparatesItIntoTwoPieces) {
  SceneDefLoad load = loadSceneDef(kScalpelScenes + "single_vessel.json");
  ASSERT_TRUE(std::holds_alternative<SceneDef>(load));
  Scene scene(std::get<SceneDef>(std::move(load)));
  ASSERT_EQ(components(scene.tissue()), 1);
  const int alive = scene.tissue().aliveLinkCount();

  // the edge sweeps down through the plane x = 1.25, between rings 2 and 3
  int k = 0;
  for (int s = 0; s <= 20; ++s) scene.step(bladeAt(Vec3(1.25, -1.0, 1.0 - 0.1 * s), k++));
  EXPECT_EQ(components(scene.tissue()), 2);
  // exactly the links between rings 2 and 3: 8 per sector (axial, diagonals, crosses)
  EXPECT_EQ(alive - scene.tissue().aliveLinkCount(), 8 * 16);
  int cut = 0;
  for (const SceneEvent& e : scene.events()) cut += e.kind == SceneEventKind::Cut ? e.count : 0;
  EXPECT_EQ(cut, 8 * 16);

  // the solver keeps working on the cut tissue
  for (int s = 0; s < 5; ++s) {
    const StepReport r = scene.step(bladeAt(Vec3(1.25, -1.0, -1.0), k++));
    EXPECT_NE(r.tissue.status, SolveStatus::InvalidInput);
  }
  EXPECT_TRUE(scene.tissueState().x.allFinite());
}

TEST(Scalpel, ABladeThatMissesCutsNothing) {
  SceneDefLoad load = loadSceneDef(kScalpelScenes + "single_vessel.json");
  ASSERT_TRUE(std::holds_alternative<SceneDef>(load));
  Scene scene(std::get<SceneDef>(std::move(load)));
  const int alive = scene.tissue().aliveLinkCount();
  for (int s = 0; s <= 5; ++s) scene.step(bladeAt(Vec3(1.25, -1.0, 2.0 + 0.1 * s), s));
  EXPECT_EQ(scene.tissue().aliveLinkCount(), alive);
}

}  // namespace
}  // namespace microsim::sim
