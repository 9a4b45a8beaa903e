// A stay stitch already placed (scene/stay_stitch.h): the instrument-tie lesson's scene
// (resources/scenes/instrument_tie.json) starts with its thread through both ends of the
// vessel, four holes in the order a needle makes them, each node on its hole; left alone it
// stays put; drawn by its long end, the thread runs through all four holes together (the
// tail shortens) and leaves the walls where they are; a stitch the scene cannot hold is a
// load error at its field.
#include "microsim/sim/scene/scene.h"

#include "support/instrument_tie_scene.h"
#include "support/knot_scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace microsim::sim {
namespace {

const std::string kStayScenes = std::string(MICROSIM_SOURCE_DIR) + "/resources/scenes/";

std::string shippedText(const std::string& name) {
  std::ifstream in(kStayScenes + name);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The instrument-tie scene, its thread in `links` links (0: as shipped, 60 links of 0.13 mm,
/// one across each 0.1 mm wall).
SceneDef stayStitchScene(int links = 0) {
  std::optional<SceneDef> def = testing::instrumentTieScene(MICROSIM_SOURCE_DIR, links);
  EXPECT_TRUE(def);
  return def ? std::move(*def) : SceneDef{};
}

/// The shipped thread and one of 0.04 mm links, three across each wall.
constexpr int kThreads[] = {0, 200};

bool onSurface(int face, const TriangleRange& r) {
  return face >= r.begin && face < r.end;
}

double largestTissueMove(const Scene& scene) {
  return (scene.tissueState().x - scene.tissue().restPositions()).colwise().norm().maxCoeff();
}

TEST(StayStitch, TheThreadStartsThroughBothWallsInPathOrder) {
  for (const int links : kThreads) {
    const SceneDef def = stayStitchScene(links);
    ASSERT_TRUE(def.needle);
    Scene scene(def);
    const auto& pierces = scene.sutureState()->pierces;
    ASSERT_EQ(pierces.size(), 4u) << links;
    // made as a needle makes them: end 0 from outside in, end 1 from inside out; each nearer
    // the needle along the thread than the one before
    const TriangleRange surfaces[4] = {def.vessels[0].outerSurface, def.vessels[0].innerSurface,
                                       def.vessels[1].innerSurface, def.vessels[1].outerSurface};
    for (std::size_t k = 0; k < 4; ++k) {
      EXPECT_TRUE(onSurface(pierces[k].face, surfaces[k])) << links << " " << k;
      EXPECT_LT((scene.sutureState()->x.col(pierces[k].node) - pierces[k].point).norm(), 1e-12)
          << k;
      if (k > 0) {
        EXPECT_LT(pierces[k].node, pierces[k - 1].node) << k;
      }
    }
    EXPECT_GT(pierces[3].node, scene.sutureModel()->swage());
    // each wall crossed by the fewest links longer together than the wall is thick (0.1 mm):
    // one link of 0.13 mm, three of 0.04 mm; the nodes between the holes inside the wall
    const double link = scene.sutureModel()->rest(scene.sutureModel()->swage());
    const int wallLinks = static_cast<int>(std::floor(0.1 / link)) + 1;
    EXPECT_EQ(wallLinks, links == 0 ? 1 : 3);
    EXPECT_EQ(pierces[0].node - pierces[1].node, wallLinks);
    EXPECT_EQ(pierces[2].node - pierces[3].node, wallLinks);
    for (const auto& [from, end] : {std::pair{1, 0}, std::pair{3, 1}}) {
      const VesselDef& v = def.vessels[static_cast<std::size_t>(end)].def;
      const Vec3 axis = v.direction.normalized();
      for (int i = pierces[static_cast<std::size_t>(from)].node + 1;
           i < pierces[static_cast<std::size_t>(from - 1)].node; ++i) {
        const Vec3 r = scene.sutureState()->x.col(i) - v.origin;
        const double radius = (r - r.dot(axis) * axis).norm();
        EXPECT_GT(radius, v.radius - v.wallThickness) << links << " node " << i;
        EXPECT_LT(radius, v.radius) << links << " node " << i;
      }
    }
    // the tail: 2 mm to the nearest link; the bites: 2.5 wall thicknesses on end 0, end 1's at
    // most a link longer
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
      EXPECT_LT(std::abs(s), 0.08) << links;
    // no hole is the trainee's: no pierce event
    EXPECT_TRUE(scene.pierces().empty());
  }
}

TEST(StayStitch, LeftAloneItStaysWhereItWasLaid) {
  for (const int links : kThreads) {
    Scene scene(stayStitchScene(links));
    const suture::Points laid = scene.sutureState()->x;
    for (int k = 0; k < 100; ++k) {
      InputFrame f;
      f.time = 0.01 * (k + 1);
      scene.step(f);
    }
    EXPECT_EQ(scene.sutureState()->pierces.size(), 4u) << links;
    EXPECT_LT((scene.sutureState()->x - laid).colwise().norm().maxCoeff(), 0.02) << links;
    EXPECT_LT(largestTissueMove(scene), 1e-3) << links;
    EXPECT_TRUE(scene.events().empty()) << links;
  }
}

TEST(StayStitch, DrawnByItsLongEndTheThreadRunsThroughAllFourHolesAndTheTailShortens) {
  for (const int links : kThreads) {
    Scene scene(stayStitchScene(links));
    const suture::Points start = scene.sutureState()->x;
    const int swage = scene.sutureModel()->swage();
    const double link = scene.sutureModel()->rest(swage);
    std::vector<int> before;
    for (const suture::Pierce& p : scene.sutureState()->pierces) before.push_back(p.node);
    // the right forceps, upright, takes the long end across its jaws 0.8 mm from the needle
    // and draws it 2.2 mm straight away from the stitch: the first millimetre or so takes up
    // the long end's bend, the rest draws thread through. (Jaws laid along the thread instead
    // lie over the needle, which cannot give way: on the fine thread the link at the swage
    // then stands a third over its length.)
    const int grasp = swage + static_cast<int>(std::lround(0.8 / link));
    const Vec3 away = (start.col(grasp) - start.col(before[3])).normalized();
    double stretch = 0.0;
    for (int k = 0; k < 450; ++k) {
      InputFrame f;
      f.time = 0.01 * (k + 1);
      f.hand(Hand::Right) = testing::forcepsAcrossThread(start, grasp, k < 2 ? 0.0 : 1.0);
      f.hand(Hand::Right).position += (k < 5 ? 0.0 : 0.005 * (k - 5)) * away;
      scene.step(f);
      for (double s : suture::linkStretches(*scene.sutureModel(), *scene.sutureState()))
        stretch = std::max(stretch, s);
    }
    const auto& after = scene.sutureState()->pierces;
    ASSERT_EQ(after.size(), 4u) << links;
    // every hole the same length of thread on: the thread ran through all four together
    const int drawn = after[0].node - before[0];
    EXPECT_GE(drawn * link, 0.5) << links;
    for (std::size_t k = 1; k < 4; ++k)
      EXPECT_EQ(after[k].node - before[k], drawn) << links << " " << k;
    EXPECT_EQ(after[0].node - after[1].node, before[0] - before[1]) << links;
    EXPECT_EQ(after[2].node - after[3].node, before[2] - before[3]) << links;
    // the thread runs through without stretching and without towing the walls
    EXPECT_LT(stretch, 0.02) << links;
    EXPECT_LT(largestTissueMove(scene), 0.01) << links;
    for (const SceneEvent& e : scene.events())
      EXPECT_TRUE(e.kind == SceneEventKind::GripSuture) << links << " " << static_cast<int>(e.kind);
  }
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
