// A scripted needle pass through both ends of a severed vessel: four pierces at the known
// points and angles, the same bits on every run, and the shipped recording in step with the
// script (and with its golden hash).
#include "support/golden_stitch.h"
#include "microsim/sim/scene/recording.h"
#include "microsim/sim/scene/scene.h"
#include "microsim/sim/scene/stitch_script.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <numeric>
#include <string>
#include <variant>
#include <vector>

namespace microsim::sim {
namespace {

const std::string kStitchTestRoot = MICROSIM_SOURCE_DIR;

SceneDef anastomosis() {
  SceneDefLoad load = loadSceneDef(kStitchTestRoot + "/resources/scenes/anastomosis.json");
  EXPECT_TRUE(std::holds_alternative<SceneDef>(load));
  return std::get<SceneDef>(std::move(load));
}

// the golden hash (tests/support/golden_stitch.h says when it may change)
using microsim::testing::kGoldenStitchHash;

std::uint64_t replay(Scene& scene, const Recording& rec) {
  for (const InputFrame& f : rec.frames) scene.step(f);
  return scene.hash();
}

TEST(Stitch, AScriptedPassGivesFourPiercesAtTheKnownPointsAndAngles) {
  // the geometry of the pass, with the tip piercing where it meets a wall (the shipped
  // scene's dent before the puncture is needle_puncture_test.cpp's)
  SceneDef def = anastomosis();
  def.needle->punctureForce = 0.0;
  const std::vector<ExpectedPierce> expected = stitchPierces(def);
  ASSERT_EQ(expected.size(), 4u);
  const Recording rec = scriptedStitch(def);
  ASSERT_FALSE(rec.frames.empty());
  Scene scene(def);
  replay(scene, rec);

  const std::vector<PierceEvent>& p = scene.pierces();
  ASSERT_EQ(p.size(), 4u);
  const VesselSurface surfaces[4] = {VesselSurface::Outer, VesselSurface::Inner,
                                     VesselSurface::Inner, VesselSurface::Outer};
  for (std::size_t k = 0; k < 4; ++k) {
    SCOPED_TRACE(k);
    EXPECT_EQ(p[k].entry, expected[k].entry);
    EXPECT_EQ(p[k].end, expected[k].end);
    EXPECT_EQ(p[k].surface, surfaces[k]);
    EXPECT_EQ(p[k].wall, VesselWall::Front);
    EXPECT_LT((p[k].restPoint - expected[k].point).norm(), 0.05);
    // the holes already made hold the wall to the turning needle, which tilts the faces the
    // exits cross by under a degree from the undeformed geometry the expectation assumes
    EXPECT_NEAR(p[k].angleDeg, expected[k].angleDeg, 1.0);
    EXPECT_NEAR(p[k].biteMm, std::abs(expected[k].point.x()) - 0.25, 0.05);
  }
  // entries, exits and grips are events too; the needle was handed over once
  int grips = 0;
  for (const SceneEvent& e : scene.events()) grips += e.kind == SceneEventKind::GripSuture;
  EXPECT_EQ(grips, 2);
  // the needle is out: its pierces hold the swage or thread nodes, nothing broke
  const suture::SutureState* s = scene.sutureState();
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->brokenLinkCount(), 0);
  ASSERT_EQ(s->pierces.size(), 4u);
  for (const suture::Pierce& pierce : s->pierces) EXPECT_GE(pierce.node, scene.sutureModel()->swage());
  EXPECT_TRUE(scene.tissueState().x.allFinite());
}

// The script puts the tools' tips on needle nodes (the holder's on the swage, the forceps' on
// node 1): the grasp takes the needle there, on the node or within a few hundredths of a
// micrometre of it (the holder's jaws, solid to the thread beyond the run they hold, nudge
// the needle by that much before the forceps takes it).
TEST(Stitch, TheScriptedToolsGripTheNeedleAtTheNodesTheScriptMeans) {
  const SceneDef def = anastomosis();
  const Recording rec = scriptedStitch(def);
  Scene scene(def);
  for (const InputFrame& f : rec.frames) {
    scene.step(f);
    for (const Hand hand : {Hand::Left, Hand::Right}) {
      if (scene.forceps(hand)->holdsSuture()) {
        ASSERT_LT(scene.forceps(hand)->heldSutureFraction(), 1e-3);
      }
    }
  }
  std::vector<int> gripped;
  for (const SceneEvent& e : scene.events())
    if (e.kind == SceneEventKind::GripSuture) gripped.push_back(e.index);
  const StitchScriptDef script;
  EXPECT_EQ(gripped, (std::vector<int>{script.gripNode, script.pullGripNode}));
}

TEST(Stitch, TheSameFramesGiveTheSameBits) {
  const SceneDef def = anastomosis();
  const Recording rec = scriptedStitch(def);
  Scene a(def);
  Scene b(def);
  EXPECT_EQ(replay(a, rec), replay(b, rec));
  // the sphere tree finds the same pierces
  SceneDef sphere = def;
  sphere.tree = CollisionTree::Sphere;
  Scene c(sphere);
  replay(c, rec);
  ASSERT_EQ(c.pierces().size(), a.pierces().size());
  for (std::size_t k = 0; k < a.pierces().size(); ++k) EXPECT_EQ(c.pierces()[k].face, a.pierces()[k].face);
}

TEST(Stitch, TheShippedRecordingIsTheScriptAndReplaysToTheGoldenHash) {
  const SceneDef def = anastomosis();
  const std::string path = kStitchTestRoot + "/resources/recordings/stitch.msrec";
  std::ifstream in(path, std::ios::binary);
  ASSERT_TRUE(in) << path;
  const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // it was written before recordings named their scene (format version 1): the script's
  // version-2 bytes without the scene's path length, (empty) path and digest, and their CRC
  std::vector<std::uint8_t> version1 = encodeRecording(scriptedStitch(def));
  version1[8] = 1;
  version1.erase(version1.begin() + 12, version1.begin() + 12 + 4 + 8);
  version1.resize(version1.size() - 4);
  const std::uint32_t crc = crc32(version1);
  for (int k = 0; k < 4; ++k) version1.push_back(static_cast<std::uint8_t>(crc >> (8 * k)));
  EXPECT_EQ(bytes, version1);
  Recording rec;
  ASSERT_TRUE(readRecording(path, rec).ok());
  Scene scene(def);
  EXPECT_EQ(replay(scene, rec), kGoldenStitchHash) << std::hex << scene.hash();
}

// The tip makes the pierces one after another and the thread follows it through them, so each
// pierce lies nearer the tip than those made before it: along the chain (node index, from the
// tip) the path is p3 < p2 < p1 < p0, at every step. Pierces the rigid needle still carries
// may share a node; on the thread each holds its own.
TEST(Stitch, ThePiercesKeepThePathOrderAtEveryStepOfTheShippedReplay) {
  const SceneDef def = anastomosis();
  Recording rec;
  ASSERT_TRUE(readRecording(kStitchTestRoot + "/resources/recordings/stitch.msrec", rec).ok());
  Scene scene(def);
  const int swage = scene.sutureModel()->swage();
  const auto nodes = [&] {
    std::string out;
    for (const suture::Pierce& p : scene.sutureState()->pierces)
      out += " " + std::to_string(p.node);
    return out;
  };
  for (const InputFrame& f : rec.frames) {
    scene.step(f);
    const std::vector<suture::Pierce>& p = scene.sutureState()->pierces;
    for (std::size_t k = 1; k < p.size(); ++k) {
      const bool inOrder =
          p[k].node < swage ? p[k].node <= p[k - 1].node : p[k].node < p[k - 1].node;
      ASSERT_TRUE(inOrder) << "step " << scene.steps() << ", pierce nodes" << nodes();
    }
  }
  // the stitch is complete: the four pierces on the thread, the first made farthest from the tip
  ASSERT_EQ(scene.sutureState()->pierces.size(), 4u) << nodes();
  EXPECT_GE(scene.sutureState()->pierces.back().node, swage) << nodes();
  // the tail drawn through after the needle lies as it was laid, not piled at the first entry:
  // its first eight links from there span more than 0.7 of their length (0.83 here; 0.30
  // when each link the holes slid by whipped it, suture_tail_test.cpp)
  const Points& x = scene.sutureState()->x;
  int entry = 0;
  for (const suture::Pierce& p : scene.sutureState()->pierces) entry = std::max(entry, p.node);
  const int tailEnd = std::min(entry + 8, static_cast<int>(x.cols()) - 1);
  EXPECT_GT((x.col(tailEnd) - x.col(entry)).norm() / scene.sutureModel()->arc(entry, tailEnd), 0.7);
}

// The shipped stitch up to the first wall's two pierces, then the same hand motion played
// backwards: the needle is drawn back out the way it came, leaving every pierce it made (those
// of the way back too) before the thread reached it. Each is released and reported once.
TEST(Stitch, ANeedleDrawnBackOutOfTheWallReleasesItsPierces) {
  const SceneDef def = anastomosis();
  Recording rec;
  ASSERT_TRUE(readRecording(kStitchTestRoot + "/resources/recordings/stitch.msrec", rec).ok());
  const std::size_t through = 130;  // the tip has entered and left the first wall's tissue
  const std::size_t before = 80;    // the tip is above the wall again
  ASSERT_GT(rec.frames.size(), through);
  std::vector<InputFrame> frames(rec.frames.begin(), rec.frames.begin() + through);
  for (std::size_t k = through - 1; k-- > before;) {
    frames.push_back(rec.frames[k]);
    frames.back().time = frames[frames.size() - 2].time + 0.01;
  }
  Scene scene(def);
  for (const InputFrame& f : frames) scene.step(f);

  EXPECT_TRUE(scene.sutureState()->pierces.empty());
  std::vector<int> released;
  for (const SceneEvent& e : scene.events()) {
    EXPECT_NE(e.kind, SceneEventKind::SuturePulledOut);
    if (e.kind == SceneEventKind::PierceReleased) released.push_back(e.index);
  }
  ASSERT_GE(scene.pierces().size(), 2u);
  std::sort(released.begin(), released.end());
  std::vector<int> all(scene.pierces().size());
  std::iota(all.begin(), all.end(), 0);
  EXPECT_EQ(released, all);
}

}  // namespace
}  // namespace microsim::sim
