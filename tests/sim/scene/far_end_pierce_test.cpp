// The needle driven through the near end, across the gap and into the far end from its lumen
// (issue 17): every pass whose tip goes through the far wall's material raises the far end's
// entry and exit, and one that stays in the lumen raises neither. The passes are the scripted
// stitch's (the holder grips the swage and turns the needle about the pass circle's centre),
// made deeper by taking a longer bite, as a trainee aiming at marks farther from the cut does.
#include "microsim/sim/scene/scene.h"
#include "microsim/sim/scene/stitch_script.h"

#include <gtest/gtest.h>

#include <cmath>
#include <ostream>
#include <string>
#include <variant>
#include <vector>

namespace microsim::sim {
namespace {

SceneDef farEndAnastomosis() {
  SceneDefLoad load = loadSceneDef(std::string(MICROSIM_SOURCE_DIR) + "/resources/scenes/anastomosis.json");
  EXPECT_TRUE(std::holds_alternative<SceneDef>(load));
  return std::get<SceneDef>(std::move(load));
}

struct FarEndPass {
  const char* name;
  double biteMm;   ///< entry distance from each cut end: the deeper the pass, the longer
  double endDeg;   ///< ψ where the holder stops turning
  bool farPierced; ///< whether the far end is entered and left
};

std::ostream& operator<<(std::ostream& os, const FarEndPass& p) { return os << p.name; }

/// What the pass raised on one end.
struct EndPierces {
  int entries = 0;
  int exits = 0;
  std::vector<VesselSurface> surfaces;
};

EndPierces piercesOnEnd(const Scene& scene, int end) {
  EndPierces out;
  for (const PierceEvent& p : scene.pierces()) {
    if (p.end != end) continue;
    (p.entry ? out.entries : out.exits) += 1;
    out.surfaces.push_back(p.surface);
  }
  return out;
}

class FarEndPierce : public ::testing::TestWithParam<FarEndPass> {};

TEST_P(FarEndPierce, TheFarEndIsPiercedExactlyWhenTheTipGoesThroughItsWall) {
  const FarEndPass pass = GetParam();
  const SceneDef def = farEndAnastomosis();
  StitchScriptDef script;
  script.biteMm = pass.biteMm;
  script.endDeg = pass.endDeg;
  script.passSeconds = 1.4;  // each pass over the same time, however far it turns
  const std::optional<StitchGeometry> g = stitchGeometry(def, script);
  ASSERT_TRUE(g.has_value());
  const Recording rec = scriptedStitch(def, script);

  // the holder turns the needle through the pass and stops (no hand-over, no pull)
  Scene scene(def);
  const int stopAt = 2 * 10 + 50 + static_cast<int>(std::lround(script.passSeconds * def.step.rateHz));
  for (int k = 0; k < stopAt; ++k) scene.step(rec.frames[static_cast<std::size_t>(k)]);

  // the near end: in at its outer surface, out at its lumen
  const EndPierces nearEnd = piercesOnEnd(scene, 0);
  EXPECT_EQ(nearEnd.entries, 1);
  EXPECT_EQ(nearEnd.exits, 1);
  ASSERT_EQ(nearEnd.surfaces.size(), 2u);
  EXPECT_EQ(nearEnd.surfaces[0], VesselSurface::Outer);
  EXPECT_EQ(nearEnd.surfaces[1], VesselSurface::Inner);

  // the far end: in at its lumen, out at its outer surface, or untouched
  const EndPierces farEnd = piercesOnEnd(scene, 1);
  const Vec3 tip = scene.sutureState()->x.col(0);
  SCOPED_TRACE("tip at " + std::to_string((tip - g->center).dot(g->eu)) + " along the axis, " +
               std::to_string((tip - g->center).dot(g->ew)) + " above the pass centre");
  if (pass.farPierced) {
    EXPECT_EQ(farEnd.entries, 1);
    EXPECT_EQ(farEnd.exits, 1);
    ASSERT_EQ(farEnd.surfaces.size(), 2u);
    EXPECT_EQ(farEnd.surfaces[0], VesselSurface::Inner);
    EXPECT_EQ(farEnd.surfaces[1], VesselSurface::Outer);
  } else {
    EXPECT_EQ(farEnd.entries, 0);
    EXPECT_EQ(farEnd.exits, 0);
  }
  for (const SceneEvent& e : scene.events()) EXPECT_NE(e.kind, SceneEventKind::TissueTear);
  EXPECT_TRUE(scene.tissueState().x.allFinite());
}

// bites from the shipped stitch's (0.25 mm: marks ±0.5 mm) to the marks at ±0.58 and ±0.65 mm
// and past them; the pass circle then dips ever deeper into the lumen and meets the far wall's
// lumen surface ever farther from the cut and more steeply
INSTANTIATE_TEST_SUITE_P(
    Passes, FarEndPierce,
    ::testing::Values(FarEndPass{"shipped", 0.25, 70.0, true}, FarEndPass{"bite030", 0.30, 70.0, true},
                      FarEndPass{"marks058", 0.33, 70.0, true}, FarEndPass{"bite035", 0.35, 70.0, true},
                      FarEndPass{"marks065", 0.40, 70.0, true}, FarEndPass{"bite045", 0.45, 75.0, true},
                      FarEndPass{"stopsInLumen", 0.33, 0.0, false}),
    [](const ::testing::TestParamInfo<FarEndPass>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace microsim::sim
