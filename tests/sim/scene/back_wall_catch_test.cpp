// The scripted back-wall catch (back_wall_catch_script.h): the needle takes the front wall of
// end 0 and goes on out through its back wall. The pass makes the four pierces the geometry
// says, in the walls it says, without hurting the tissue otherwise; the shipped recording is
// the script, bit for bit, and replays to its pinned hash.
#include "microsim/sim/scene/back_wall_catch_script.h"
#include "microsim/sim/scene/recorded_scene.h"
#include "microsim/sim/scene/recording.h"
#include "microsim/sim/scene/scene.h"
#include "support/golden_stitch.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>
#include <variant>
#include <vector>

namespace microsim::sim {
namespace {

const std::string kCatchTestRoot = MICROSIM_SOURCE_DIR;
const std::string kCatchScene = kCatchTestRoot + "/resources/scenes/anastomosis.json";

SceneDef anastomosis() {
  SceneDefLoad load = loadSceneDef(kCatchScene);
  EXPECT_TRUE(std::holds_alternative<SceneDef>(load));
  return std::get<SceneDef>(std::move(load));
}

struct CatchRun {
  std::vector<PierceEvent> pierces;
  std::vector<SceneEventKind> events;
  std::uint64_t hash = 0;
};

CatchRun run(const SceneDef& def, const Recording& rec) {
  Scene scene(def);
  CatchRun out;
  for (const InputFrame& f : rec.frames) scene.step(f);
  for (const SceneEvent& e : scene.events()) out.events.push_back(e.kind);
  out.pierces = scene.pierces();
  out.hash = scene.hash();
  return out;
}

TEST(BackWallCatch, ThePassTakesTheFrontWallThenLeavesThroughTheBackWallOfTheSameEnd) {
  const SceneDef def = anastomosis();
  const Recording rec = scriptedBackWallCatch(def);
  ASSERT_FALSE(rec.frames.empty());
  const CatchRun r = run(def, rec);

  // in through the front wall's outer surface, out into the lumen, into the back wall from
  // the lumen (the catch), out through its outer surface: all in end 0, a bite from its cut
  ASSERT_EQ(r.pierces.size(), 4u);
  const bool entries[4] = {true, false, true, false};
  const VesselSurface surfaces[4] = {VesselSurface::Outer, VesselSurface::Inner,
                                     VesselSurface::Inner, VesselSurface::Outer};
  const VesselWall walls[4] = {VesselWall::Front, VesselWall::Front, VesselWall::Back,
                               VesselWall::Back};
  for (std::size_t k = 0; k < 4; ++k) {
    const PierceEvent& p = r.pierces[k];
    EXPECT_EQ(p.entry, entries[k]) << k;
    EXPECT_EQ(p.end, 0) << k;
    EXPECT_EQ(p.surface, surfaces[k]) << k;
    EXPECT_EQ(p.wall, walls[k]) << k;
    EXPECT_NEAR(p.biteMm, BackWallCatchDef{}.biteMm, 0.03) << k;
  }

  // the needle went where it was turned: nothing was torn or over-stretched on the way
  ASSERT_GT(def.limits.overstretch, 0.0);
  for (SceneEventKind k : r.events) {
    EXPECT_NE(k, SceneEventKind::TissueTear);
    EXPECT_NE(k, SceneEventKind::TissueOverStretch);
  }
}

TEST(BackWallCatch, AVesselWithoutAHandForEachToolHasNoCatchToScript) {
  SceneDef def = anastomosis();
  def.forceps[0].reset();
  EXPECT_FALSE(backWallCatchGeometry(def));
  EXPECT_TRUE(scriptedBackWallCatch(def).frames.empty());
}

TEST(BackWallCatch, TheShippedRecordingIsTheScriptAndReplaysToItsHash) {
  const SceneDef def = anastomosis();
  // the shipped file names its scene by file name (found among the shipped scenes wherever
  // they are installed) and by the digest of its bytes
  Recording script = scriptedBackWallCatch(def);
  script.scene = {"anastomosis.json", sceneFileDigest(kCatchScene).value_or(0)};
  const std::string path = kCatchTestRoot + "/resources/recordings/back_wall_catch.msrec";
  std::ifstream in(path, std::ios::binary);
  ASSERT_TRUE(in) << path;
  const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                        std::istreambuf_iterator<char>());
  EXPECT_EQ(bytes, encodeRecording(script));

  Recording rec;
  ASSERT_TRUE(readRecording(path, rec).ok());
  EXPECT_EQ(run(def, rec).hash, microsim::testing::kGoldenBackWallCatchHash)
      << std::hex << run(def, rec).hash;
}

}  // namespace
}  // namespace microsim::sim
