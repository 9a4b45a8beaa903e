// A stay stitch already placed (scene/stay_stitch.h): the instrument-tie lesson's scene
// (resources/scenes/instrument_tie.json) starts with its thread through both ends of the
// vessel, four holes in the order a needle makes them, each node on its hole; left alone it
// stays put; drawn by its long end, the thread runs through all four holes together (the
// tail shortens) and leaves the walls where they are; a stitch the scene cannot hold is a
// load error at its field.
#include "microsim/sim/scene/scene.h"

#include "support/knot_scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <variant>

namespace microsim::sim {
namespace {

const std::string kStayScenes = std::string(MICROSIM_SOURCE_DIR) + "/resources/scenes/";

SceneDef stayStitchScene() {
  SceneDefLoad load = loadSceneDef(kStayScenes + "instrument_tie.json");
  EXPECT_TRUE(std::holds_alternative<SceneDef>(load));
  return std::holds_alternative<SceneDef>(load) ? std::get<SceneDef>(std::move(load)) : SceneDef{};
}

bool onSurface(int face, const TriangleRange& r) {
  return face >= r.begin && face < r.end;
}

double largestTissueMove(const Scene& scene) {
  return (scene.tissueState().x - scene.tissue().restPositions()).colwise().norm().maxCoeff();
}

TEST(StayStitch, TheThreadStartsThroughBothWallsInPathOrder) {
  const SceneDef def = stayStitchScene();
  ASSERT_TRUE(def.needle);
  Scene scene(def);
  const auto& pierces = scene.sutureState()->pierces;
  ASSERT_EQ(pierces.size(), 4u);
  // made as a needle makes them: end 0 from outside in, end 1 from inside out; each nearer
  // the needle along the thread than the one before
  const TriangleRange surfaces[4] = {def.vessels[0].outerSurface, def.vessels[0].innerSurface,
                                     def.vessels[1].innerSurface, def.vessels[1].outerSurface};
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_TRUE(onSurface(pierces[k].face, surfaces[k])) << k;
    EXPECT_LT((scene.sutureState()->x.col(pierces[k].node) - pierces[k].point).norm(), 1e-12) << k;
    if (k > 0) {
      EXPECT_LT(pierces[k].node, pierces[k - 1].node) << k;
    }
  }
  EXPECT_GT(pierces[3].node, scene.sutureModel()->swage());
  // the tail: 2 mm to the nearest link; the bites: 2.5 wall thicknesses on end 0, end 1's at
  // most a link longer
  const double link = scene.sutureModel()->rest(scene.sutureModel()->swage());
  const int last = scene.sutureModel()->nodeCount() - 1;
  EXPECT_NEAR((last - pierces[0].node) * link, 2.0, 0.5 * link);
  const auto biteOf = [&](int end, const Vec3& point) {
    const VesselDef& v = def.vessels[static_cast<std::size_t>(end)].def;
    return (v.origin + v.length * v.direction.normalized() - point).dot(v.direction.normalized());
  };
  EXPECT_NEAR(biteOf(0, pierces[0].point), 0.25, 0.01);
  EXPECT_GE(biteOf(1, pierces[3].point), 0.25 - 0.01);
  EXPECT_LE(biteOf(1, pierces[3].point), 0.25 + link + 0.01);
  // every link near its rest length: the holes lie on the faceted wall, a few µm off the
  // cylinder the path was laid on
  for (double s : suture::linkStretches(*scene.sutureModel(), *scene.sutureState()))
    EXPECT_LT(std::abs(s), 0.08);
  // no hole is the trainee's: no pierce event
  EXPECT_TRUE(scene.pierces().empty());
}

TEST(StayStitch, LeftAloneItStaysWhereItWasLaid) {
  Scene scene(stayStitchScene());
  const suture::Points laid = scene.sutureState()->x;
  for (int k = 0; k < 100; ++k) {
    InputFrame f;
    f.time = 0.01 * (k + 1);
    scene.step(f);
  }
  EXPECT_EQ(scene.sutureState()->pierces.size(), 4u);
  EXPECT_LT((scene.sutureState()->x - laid).colwise().norm().maxCoeff(), 0.02);
  EXPECT_LT(largestTissueMove(scene), 1e-3);
  EXPECT_TRUE(scene.events().empty());
}

TEST(StayStitch, DrawnByItsLongEndTheThreadRunsThroughAllFourHolesAndTheTailShortens) {
  Scene scene(stayStitchScene());
  const suture::Points start = scene.sutureState()->x;
  const int swage = scene.sutureModel()->swage();
  std::vector<int> before;
  for (const suture::Pierce& p : scene.sutureState()->pierces) before.push_back(p.node);
  // the right forceps takes the long end 6 links from the needle and draws it 2.2 mm
  // straight away from the stitch: the first millimetre or so takes up the long end's bend,
  // the rest draws thread through
  const Vec3 away = (start.col(swage + 6) - start.col(before[3])).normalized();
  double stretch = 0.0;
  for (int k = 0; k < 450; ++k) {
    InputFrame f;
    f.time = 0.01 * (k + 1);
    f.hand(Hand::Right) = testing::forcepsOnThreadEnd(start, swage + 6, -1, k < 2 ? 0.0 : 1.0);
    f.hand(Hand::Right).position += (k < 5 ? 0.0 : 0.005 * (k - 5)) * away;
    scene.step(f);
    for (double s : suture::linkStretches(*scene.sutureModel(), *scene.sutureState()))
      stretch = std::max(stretch, s);
  }
  const auto& after = scene.sutureState()->pierces;
  ASSERT_EQ(after.size(), 4u);
  // every hole the same number of nodes on: the thread ran through all four together
  const int drawn = after[0].node - before[0];
  EXPECT_GE(drawn, 4);
  for (std::size_t k = 1; k < 4; ++k) EXPECT_EQ(after[k].node - before[k], drawn) << k;
  EXPECT_EQ(after[0].node - after[1].node, before[0] - before[1]);
  EXPECT_EQ(after[2].node - after[3].node, before[2] - before[3]);
  // the thread runs through without stretching and without towing the walls
  EXPECT_LT(stretch, 0.02);
  EXPECT_LT(largestTissueMove(scene), 0.01);
  for (const SceneEvent& e : scene.events())
    EXPECT_TRUE(e.kind == SceneEventKind::GripSuture) << static_cast<int>(e.kind);
}

std::string shippedText(const std::string& name) {
  std::ifstream in(kStayScenes + name);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

SceneError stayStitchErrorOf(const std::string& text) {
  SceneDefLoad load =
      parseSceneDef(text, "stay.json", std::string(MICROSIM_SOURCE_DIR) + "/resources/meshes");
  EXPECT_TRUE(std::holds_alternative<SceneError>(load));
  return std::holds_alternative<SceneError>(load) ? std::get<SceneError>(load) : SceneError{};
}

std::string withStayStitch(std::string text, const std::string& stitch) {
  const std::string at = R"("stay_stitch": {"angle_deg": 0, "bite_walls": 2.5, "tail_mm": 2.0})";
  const std::size_t where = text.find(at);
  EXPECT_NE(where, std::string::npos);
  return where == std::string::npos ? text
                                    : text.replace(where, at.size(), R"("stay_stitch": )" + stitch);
}

TEST(StayStitch, AStitchTheSceneCannotHoldIsALoadErrorAtItsField) {
  const std::string shipped = shippedText("instrument_tie.json");
  struct Case {
    std::string stitch;
    SceneErrorKind kind;
    std::string field;
  };
  const Case cases[] = {
      {R"({"angle_deg": 0, "bite_walls": 0, "tail_mm": 2.0})", SceneErrorKind::InvalidValue,
       "tools.needle.stay_stitch.bite_walls"},
      {R"({"angle_deg": "top"})", SceneErrorKind::WrongType, "tools.needle.stay_stitch.angle_deg"},
      {R"({"angle": 0})", SceneErrorKind::UnknownField, "tools.needle.stay_stitch.angle"},
      // the whole bite beyond the end's 3 mm
      {R"({"bite_walls": 40})", SceneErrorKind::InvalidValue, "tools.needle.stay_stitch"},
      // a 7.5 mm tail leaves the needle no thread
      {R"({"tail_mm": 7.5})", SceneErrorKind::InvalidValue, "tools.needle.stay_stitch"},
  };
  for (const Case& c : cases) {
    const SceneError e = stayStitchErrorOf(withStayStitch(shipped, c.stitch));
    EXPECT_EQ(e.kind, c.kind) << c.stitch;
    EXPECT_EQ(e.field, c.field) << c.stitch;
  }
  // a vessel that is not severed has no two ends to stitch
  std::string single = shippedText("single_vessel.json");
  single.replace(single.find(R"("scalpel")"), 0,
                 R"("needle": {"stay_stitch": {"angle_deg": 0}}, )");
  const SceneError e = stayStitchErrorOf(single);
  EXPECT_EQ(e.kind, SceneErrorKind::InvalidValue);
  EXPECT_EQ(e.field, "tools.needle.stay_stitch");
}

}  // namespace
}  // namespace microsim::sim
