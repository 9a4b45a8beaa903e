// The needle's tip on the shipped scene's wall: it dents the wall before it punctures it, the
// hole is where it first touched, and a tip drawn back before the puncture leaves the wall
// whole and at rest (tools/needle_indent.h).
#include "microsim/sim/scene/scene.h"
#include "microsim/sim/scene/stitch_script.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <variant>
#include <vector>

namespace microsim::sim {
namespace {

SceneDef shippedAnastomosis() {
  SceneDefLoad load = loadSceneDef(std::string(MICROSIM_SOURCE_DIR) + "/resources/scenes/anastomosis.json");
  EXPECT_TRUE(std::holds_alternative<SceneDef>(load));
  return std::get<SceneDef>(std::move(load));
}

double largestDisplacement(const Scene& scene, const Points& rest) {
  return (scene.tissueState().x - rest).colwise().norm().maxCoeff();
}

int firstEntryStep(const Scene& scene) {
  for (const SceneEvent& e : scene.events())
    if (e.kind == SceneEventKind::PierceEntry) return e.step;
  return -1;
}

TEST(NeedlePuncture, TheShippedWallDentsUnderTheTipBeforeItIsPunctured) {
  const SceneDef def = shippedAnastomosis();
  ASSERT_GT(def.needle->punctureForce, 0.0);
  const Recording rec = scriptedStitch(def);

  // where a tip that pierces at once meets the wall
  SceneDef instantDef = def;
  instantDef.needle->punctureForce = 0.0;
  Scene instant(instantDef);
  int touch = -1;
  for (std::size_t i = 0; i < rec.frames.size() && touch < 0; ++i) {
    instant.step(rec.frames[i]);
    touch = firstEntryStep(instant);
  }
  ASSERT_GE(touch, 0);

  // the shipped scene: the wall gives under the tip, and nothing is pierced until it is through
  Scene scene(def);
  const Points rest = scene.tissueState().x;
  double dentAtPuncture = 0.0;
  for (const InputFrame& f : rec.frames) {
    const double dent = largestDisplacement(scene, rest);
    scene.step(f);
    if (firstEntryStep(scene) == scene.steps() - 1 && dentAtPuncture == 0.0) dentAtPuncture = dent;
  }
  const int punctured = firstEntryStep(scene);
  EXPECT_GT(punctured, touch + 2);
  // a visible dent, about the wall's thickness (0.1 mm), and no more
  EXPECT_GT(dentAtPuncture, 0.03);
  EXPECT_LT(dentAtPuncture, 0.2);

  // the hole is where the tip first touched, on the undeformed wall
  const std::vector<ExpectedPierce> expected = stitchPierces(def);
  ASSERT_EQ(scene.pierces().size(), 4u);
  EXPECT_LT((scene.pierces()[0].restPoint - expected[0].point).norm(), 0.02);
  EXPECT_LT((scene.pierces()[2].restPoint - expected[2].point).norm(), 0.02);
  // the pass still goes in, out, in, out, and nothing tore
  for (std::size_t k = 0; k < 4; ++k) EXPECT_EQ(scene.pierces()[k].entry, k % 2 == 0) << k;
  for (const SceneEvent& e : scene.events()) EXPECT_NE(e.kind, SceneEventKind::TissueTear);
  EXPECT_TRUE(scene.tissueState().x.allFinite());
}

TEST(NeedlePuncture, ATipDrawnBackBeforeThePunctureLeavesTheWallWholeAndAtRest) {
  const SceneDef def = shippedAnastomosis();
  const Recording rec = scriptedStitch(def);

  // find the step of the puncture, then press only until two steps before it
  Scene probe(def);
  int punctured = -1;
  for (std::size_t i = 0; i < rec.frames.size() && punctured < 0; ++i) {
    probe.step(rec.frames[i]);
    punctured = firstEntryStep(probe);
  }
  ASSERT_GT(punctured, 20);
  const std::size_t pressed = static_cast<std::size_t>(punctured) - 2;
  std::vector<InputFrame> frames(rec.frames.begin(), rec.frames.begin() + static_cast<std::ptrdiff_t>(pressed) + 1);
  for (std::size_t k = pressed; k-- > pressed - 20;) {
    frames.push_back(rec.frames[k]);
    frames.back().time = frames[frames.size() - 2].time + 0.01;
  }

  Scene scene(def);
  const Points rest = scene.tissueState().x;
  double deepest = 0.0;
  for (const InputFrame& f : frames) {
    scene.step(f);
    deepest = std::max(deepest, largestDisplacement(scene, rest));
  }
  EXPECT_GT(deepest, 0.02);
  EXPECT_TRUE(scene.pierces().empty());
  // let the wall settle with the hands still
  for (int k = 0; k < 30; ++k) {
    InputFrame still = frames.back();
    still.time += 0.01 * (k + 1);
    scene.step(still);
  }
  EXPECT_TRUE(scene.pierces().empty());
  EXPECT_LT(largestDisplacement(scene, rest), 1e-3);
}

// A hand on keys moves the needle a notch, then holds it still for a step or two. The tip that
// stands pressed into a wall between notches keeps denting it until it punctures; when the dent
// was judged by the sign of a sub-micrometre offset, a standing tip "drew back" at random and a
// later notch carried it through the far wall from the lumen with no pierce.
TEST(NeedlePuncture, ATipMovedInNotchesWithStillStepsBetweenStillPunctures) {
  const SceneDef def = shippedAnastomosis();
  for (const double bite : {0.30, 0.33})
    for (const int hold : {2, 3}) {
      SCOPED_TRACE("bite " + std::to_string(bite) + " mm, each frame held " + std::to_string(hold) + " steps");
      StitchScriptDef script;
      script.biteMm = bite;
      const Recording rec = scriptedStitch(def, script);
      // the holder's grip, the carry to the start and the pass through both ends (no hand-over)
      const int passFrames = 2 * 10 + 50 + static_cast<int>(std::lround(script.passSeconds * def.step.rateHz));
      Scene scene(def);
      double time = 0.0;
      for (int i = 0; i < passFrames; ++i)
        for (int k = 0; k < hold; ++k) {
          InputFrame held = rec.frames[static_cast<std::size_t>(i)];
          time += 0.01;
          held.time = time;
          scene.step(held);
        }
      ASSERT_EQ(scene.pierces().size(), 4u);
      for (std::size_t k = 0; k < 4; ++k) {
        EXPECT_EQ(scene.pierces()[k].entry, k % 2 == 0) << k;
        EXPECT_EQ(scene.pierces()[k].end, k < 2 ? 0 : 1) << k;
      }
      EXPECT_TRUE(scene.tissueState().x.allFinite());
    }
}

}  // namespace
}  // namespace microsim::sim
