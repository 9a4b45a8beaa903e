// Tissue stretch limits (SceneDef::limits): an over-stretch event where a link's stretch
// rises above the threshold, once, and tears that remove links like a cut.
#include "microsim/sim/scene/recording.h"
#include "microsim/sim/scene/scene.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>
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

std::vector<SceneEvent> tissueLimitEventsOf(const Scene& scene, SceneEventKind kind) {
  std::vector<SceneEvent> out;
  for (const SceneEvent& e : scene.events())
    if (e.kind == kind) out.push_back(e);
  return out;
}

TEST(TissueLimits, AnOverStretchIsReportedOnceWhenItStarts) {
  Scene scene(chain(R"({"overstretch": 0.3})"));
  for (int s = 0; s < 5; ++s) scene.step(InputFrame{});
  const std::vector<SceneEvent> over = tissueLimitEventsOf(scene, SceneEventKind::TissueOverStretch);
  ASSERT_EQ(over.size(), 2u);
  for (int l = 0; l < 2; ++l) {
    EXPECT_EQ(over[static_cast<std::size_t>(l)].index, l);
    EXPECT_EQ(over[static_cast<std::size_t>(l)].count, 500);  // per-mille
    EXPECT_EQ(over[static_cast<std::size_t>(l)].step, 0);
  }
  EXPECT_TRUE(tissueLimitEventsOf(scene, SceneEventKind::TissueTear).empty());
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
  const std::vector<SceneEvent> tears = tissueLimitEventsOf(scene, SceneEventKind::TissueTear);
  ASSERT_EQ(tears.size(), 1u);
  EXPECT_EQ(tears[0].index, 0);
  EXPECT_EQ(tears[0].count, 2);
  EXPECT_EQ(scene.tissue().aliveLinkCount(), 0);
  // the torn chain goes on stepping without further events
  scene.step(InputFrame{});
  EXPECT_EQ(scene.events().size(), 1u);
}

// --- a forceps on the shipped orientation scene's wall (two vessel ends, wall material,
// newton, over-stretch 0.3, tear 0.6) ---

const std::string kLimitsScenes = std::string(MICROSIM_SOURCE_DIR) + "/resources/scenes/";

// the right forceps, jaws pointing down onto the wall (tool +x → scene +z) and opening
// across the vessel (tool y → scene y), tip at `tip` (mm)
InputFrame graspFrame(const Vec3& tip, double closure, int k) {
  InputFrame f;
  f.time = 0.01 * k;
  f.hand(Hand::Left).instrument = Instrument::None;
  HandInput& h = f.hand(Hand::Right);
  h.instrument = Instrument::Forceps;
  h.tracked = true;
  h.position = tip;
  h.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(-0.5 * std::numbers::pi, Vec3::UnitY()));
  h.closure = closure;
  return f;
}

// the largest stretch (l − r)/r of an alive link
double largestStretch(const Scene& scene) {
  const SpringModel& m = scene.tissue();
  const Points& x = scene.tissueState().x;
  double worst = 0.0;
  for (const Link& l : m.links())
    if (l.alive && l.rest > 0.0) worst = std::max(worst, ((x.col(l.b) - x.col(l.a)).norm() - l.rest) / l.rest);
  return worst;
}

struct DragResult {
  int held = 0;             ///< tissue nodes the forceps took
  int overStretches = 0;
  int tears = 0;
  double largestStretch = 0.0;  ///< over every step's end, alive links
};

// the jaws close (crossing close_at at 0.8) on the top of end 0's cut ring, the tool's tip
// 0.02 mm into its outer surface (the open tips stand above it, astride the edge), then the
// closed forceps moves by `drag` (mm) in 0.1 mm steps and holds there; every step is checked:
// finite, and no alive link beyond the tear strain
DragResult dragCutEdge(const Vec3& drag) {
  SceneDefLoad load = loadSceneDef(kLimitsScenes + "orientation.json");
  EXPECT_TRUE(std::holds_alternative<SceneDef>(load));
  Scene scene(std::get<SceneDef>(std::move(load)));
  const double tear = scene.def().limits.tear;
  EXPECT_GT(tear, 0.0);
  const SceneVessel& end0 = scene.def().vessels.front();
  const Vec3 cut = end0.def.origin + end0.def.length * end0.def.direction;
  const Vec3 start = cut + Vec3(0, 0, end0.def.radius - 0.02);

  DragResult r;
  int k = 0;
  auto step = [&](const Vec3& tip, double closure) {
    scene.step(graspFrame(tip, closure, k++));
    EXPECT_TRUE(scene.tissueState().x.allFinite()) << "step " << k;
    const double worst = largestStretch(scene);
    EXPECT_LE(worst, tear) << "an alive link past the tear strain at step " << k;
    r.largestStretch = std::max(r.largestStretch, worst);
  };
  step(start, 0.0);
  step(start, 0.8);
  r.held = scene.forceps(Hand::Right) ? static_cast<int>(scene.forceps(Hand::Right)->heldNodes().size()) : 0;
  const int steps = std::max(1, static_cast<int>(std::ceil(drag.norm() / 0.1)));
  for (int s = 1; s <= steps; ++s) step(start + drag * (static_cast<double>(s) / steps), 1.0);
  for (int s = 0; s < 5; ++s) step(start + drag, 1.0);
  r.overStretches = static_cast<int>(tissueLimitEventsOf(scene, SceneEventKind::TissueOverStretch).size());
  r.tears = static_cast<int>(tissueLimitEventsOf(scene, SceneEventKind::TissueTear).size());
  return r;
}

TEST(TissueLimits, AGentleDragOfTheGraspedWallRaisesNoEvent) {
  // 0.3 mm towards the other end, the way the ends are brought together
  const DragResult r = dragCutEdge(Vec3(0.3, 0, 0));
  ASSERT_GT(r.held, 0);
  EXPECT_EQ(r.overStretches, 0);
  EXPECT_EQ(r.tears, 0);
  EXPECT_LT(r.largestStretch, 0.3);
  RecordProperty("largest_stretch", std::to_string(r.largestStretch));
}

TEST(TissueLimits, ARoughDragOfTheGraspedWallOverStretchesOrTearsIt) {
  const DragResult r = dragCutEdge(Vec3(2.0, 0, 0));
  ASSERT_GT(r.held, 0);
  EXPECT_GT(r.overStretches + r.tears, 0);
}

TEST(TissueLimits, ARoughLiftOfTheGraspedWallOverStretchesOrTearsIt) {
  const DragResult r = dragCutEdge(Vec3(0, 0, 2.0));
  ASSERT_GT(r.held, 0);
  EXPECT_GT(r.overStretches + r.tears, 0);
}

// the shipped stitch replayed on the shipped scene: no alive link beyond the tear strain at
// the end of any step (a link past it is torn, with an event), and nothing goes NaN
TEST(TissueLimits, TheShippedStitchLeavesNoLinkPastTheTearStrain) {
  SceneDefLoad load = loadSceneDef(kLimitsScenes + "anastomosis.json");
  ASSERT_TRUE(std::holds_alternative<SceneDef>(load));
  Recording rec;
  ASSERT_TRUE(readRecording(std::string(MICROSIM_SOURCE_DIR) + "/resources/recordings/stitch.msrec", rec).ok());
  Scene scene(std::get<SceneDef>(std::move(load)));
  const double tear = scene.def().limits.tear;
  ASSERT_GT(tear, 0.0);
  double largest = 0.0;
  for (const InputFrame& f : rec.frames) {
    scene.step(f);
    ASSERT_TRUE(scene.tissueState().x.allFinite()) << "step " << scene.steps();
    const double worst = largestStretch(scene);
    largest = std::max(largest, worst);
    EXPECT_LE(worst, tear) << "step " << scene.steps();
  }
  RecordProperty("largest_stretch", std::to_string(largest));
  RecordProperty("tears", std::to_string(tissueLimitEventsOf(scene, SceneEventKind::TissueTear).size()));
  RecordProperty("over_stretches", std::to_string(tissueLimitEventsOf(scene, SceneEventKind::TissueOverStretch).size()));
}

TEST(TissueLimits, BadContactSettingsAreRejectedByField) {
  for (const char* bad : {R"({"stiffness": -1})", R"({"thickness": 0})", R"({"tissue": 1})", R"({"reach": "far"})"}) {
    SCOPED_TRACE(bad);
    SceneDefLoad load = parseSceneDef(std::string(R"({"objects": [{"type": "lattice", "size": [2, 2, 2]}],
      "collision": )") + bad + "}");
    ASSERT_TRUE(std::holds_alternative<SceneError>(load));
    EXPECT_EQ(std::get<SceneError>(load).field.rfind("collision.", 0), 0u) << std::get<SceneError>(load).field;
  }
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
