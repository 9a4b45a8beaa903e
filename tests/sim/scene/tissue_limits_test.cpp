// Tissue stretch limits (SceneDef::limits): an over-stretch event where a link's stretch
// rises above the threshold, once, and tears that remove links like a cut.
#include "microsim/sim/scene/scene.h"

#include <gtest/gtest.h>

#include <string>
#include <variant>
#include <vector>

namespace microsim::sim {
namespace {

// a chain 0 – 1 – 2 of unit links, 0 fixed, 2 pulled 1 mm along it: at equilibrium both
// links are stretched by 0.5
SceneDef chain(const std::string& tissue) {
  const std::string text = R"({"objects": [{"type": "spring-mesh",
      "nodes": [[0, 0, 0], [1, 0, 0], [2, 0, 0]], "links": [[0, 1, 10], [1, 2, 10]],
      "fixed": [0], "controls": [{"node": 2, "displacement": [1, 0, 0]}]}],
    "solver": {"name": "newton", "iterations": 50, "tolerance": 1e-10},
    "tissue": )" + tissue + "}";
  SceneDefLoad load = parseSceneDef(text);
  EXPECT_TRUE(std::holds_alternative<SceneDef>(load));
  return std::get<SceneDef>(std::move(load));
}

std::vector<SceneEvent> eventsOf(const Scene& scene, SceneEventKind kind) {
  std::vector<SceneEvent> out;
  for (const SceneEvent& e : scene.events())
    if (e.kind == kind) out.push_back(e);
  return out;
}

TEST(TissueLimits, AnOverStretchIsReportedOnceWhenItStarts) {
  Scene scene(chain(R"({"overstretch": 0.3})"));
  for (int s = 0; s < 5; ++s) scene.step(InputFrame{});
  const std::vector<SceneEvent> over = eventsOf(scene, SceneEventKind::TissueOverStretch);
  ASSERT_EQ(over.size(), 2u);
  for (int l = 0; l < 2; ++l) {
    EXPECT_EQ(over[static_cast<std::size_t>(l)].index, l);
    EXPECT_EQ(over[static_cast<std::size_t>(l)].count, 500);  // per-mille
    EXPECT_EQ(over[static_cast<std::size_t>(l)].step, 0);
  }
  EXPECT_TRUE(eventsOf(scene, SceneEventKind::TissueTear).empty());
  EXPECT_EQ(scene.tissue().aliveLinkCount(), 2);
}

TEST(TissueLimits, BelowTheThresholdNothingHappens) {
  Scene scene(chain(R"({"overstretch": 0.6, "tear": 0.7})"));
  for (int s = 0; s < 3; ++s) scene.step(InputFrame{});
  EXPECT_TRUE(scene.events().empty());
}

TEST(TissueLimits, ALinkPastTheTearThresholdIsRemoved) {
  Scene scene(chain(R"({"tear": 0.4})"));
  const StepReport r = scene.step(InputFrame{});
  EXPECT_EQ(r.events, 1);
  const std::vector<SceneEvent> tears = eventsOf(scene, SceneEventKind::TissueTear);
  ASSERT_EQ(tears.size(), 1u);
  EXPECT_EQ(tears[0].index, 0);
  EXPECT_EQ(tears[0].count, 2);
  EXPECT_EQ(scene.tissue().aliveLinkCount(), 0);
  // the torn chain goes on stepping without further events
  scene.step(InputFrame{});
  EXPECT_EQ(scene.events().size(), 1u);
}

TEST(TissueLimits, BadLimitsAreRejectedByField) {
  SceneDefLoad load = parseSceneDef(R"({"objects": [{"type": "lattice", "size": [2, 2, 2]}],
    "tissue": {"overstretch": -1}})");
  ASSERT_TRUE(std::holds_alternative<SceneError>(load));
  EXPECT_EQ(std::get<SceneError>(load).field, "tissue.overstretch");
  load = parseSceneDef(R"({"objects": [{"type": "lattice", "size": [2, 2, 2]}],
    "tissue": {"strech": 1}})");
  ASSERT_TRUE(std::holds_alternative<SceneError>(load));
  EXPECT_EQ(std::get<SceneError>(load).kind, SceneErrorKind::UnknownField);
}

}  // namespace
}  // namespace microsim::sim
