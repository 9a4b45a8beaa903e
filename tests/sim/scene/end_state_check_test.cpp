// checkEndState on the shipped anastomosis's vessel (resources/scenes/anastomosis.json) with
// stitches laid as stay stitches (scene/stay_stitch.h) and the tissue or thread moved to known
// shapes: a clean stitch, laid or left alone in its scene, shows none of the three lapses; the
// tissue squeezed inside a stitch's loop is an over-tight stitch at the stitch; thread in the
// lumen beyond the margin is found at its deepest node, not within the margin and not on a
// stitch's crossing; one end's edge ridden over the other is an overlap where it rides, and
// neither a step between edges apart nor edges past each other face to face is one.
#include "microsim/sim/scene/end_state_check.h"

#include "microsim/sim/scene/circumference_frame.h"
#include "microsim/sim/scene/scene.h"
#include "microsim/sim/scene/scene_def.h"
#include "microsim/sim/scene/stay_stitch.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <variant>

namespace microsim::sim {
namespace {

const std::string kEndStateScenes = std::string(MICROSIM_SOURCE_DIR) + "/resources/scenes/";

SceneDef endStateScene(const std::string& name = "anastomosis.json") {
  SceneDefLoad load = loadSceneDef(kEndStateScenes + name);
  EXPECT_TRUE(std::holds_alternative<SceneDef>(load));
  return std::holds_alternative<SceneDef>(load) ? std::get<SceneDef>(std::move(load)) : SceneDef{};
}

/// The thread of a stay stitch at `deg` (2.5 wall thicknesses, 2 mm of tail), as a state.
suture::SutureState endStateStitch(const SceneDef& def, double deg) {
  StayStitchDef stitch;
  stitch.angleDeg = deg;
  auto laid = layStayStitch(def, stitch);
  EXPECT_TRUE(std::holds_alternative<LaidStayStitch>(laid));
  suture::SutureState s;
  if (!std::holds_alternative<LaidStayStitch>(laid)) return s;
  const LaidStayStitch& l = std::get<LaidStayStitch>(laid);
  s.x = l.shape;
  s.xPrev = l.shape;
  s.alive.assign(static_cast<std::size_t>(l.shape.cols() - 1), 1);
  s.pierces = l.pierces;
  return s;
}

/// The frame the check's angles turn in: end 0's axis, 0° toward the camera.
CircumferenceFrame endStateFrame(const SceneDef& def) {
  const VesselDef& v = def.vessels[0].def;
  const Vec3 axis = v.direction.normalized();
  return circumferenceFrame(axis, def.camera.eye - (v.origin + v.length * axis));
}

/// Degrees between two angles, [0, 180].
double endStateApart(double a, double b) {
  return std::abs(std::remainder(a - b, 360.0));
}

/// Moves the cut ring (both hulls) of end `end` by w(angle)·(`forward` mm along its axis,
/// toward the other end, and `inward` mm toward its axis), w = cos of the angle from `deg`
/// stretched so that it falls to 0 at `spanDeg` away (0 beyond): the edge bent where a stitch
/// or an overlap is.
void endStateBendCutRing(const SceneDef& def, Points& x, int end, double deg, double spanDeg,
                         double forward, double inward) {
  const SceneVessel& v = def.vessels[static_cast<std::size_t>(end)];
  const CircumferenceFrame frame = endStateFrame(def);
  const Vec3 axis = v.def.direction.normalized();
  const Points& rest = def.tissue.model.restPositions();
  const int p = v.def.nodesPerRing;
  for (int hull = 0; hull < 2; ++hull)
    for (int j = 0; j < p; ++j) {
      const int node = v.firstNode + ((v.def.rings - 1) * 2 + hull) * p + j;
      Vec3 radial = rest.col(node) - v.def.origin;
      radial -= radial.dot(axis) * axis;
      const double off = endStateApart(frame.angleDeg(radial), deg);
      if (off >= spanDeg) continue;
      const double w = std::cos(0.5 * std::numbers::pi * off / spanDeg);
      x.col(node) += w * (forward * axis - inward * radial.normalized());
    }
}

int endStateCount(const EndStateResult& r, EndStateKind kind) {
  int n = 0;
  for (const EndStateFinding& f : r.findings) n += f.kind == kind ? 1 : 0;
  return n;
}

TEST(EndStateCheck, ACleanStayStitchShowsNoneOfTheThree) {
  const SceneDef def = endStateScene();
  for (double deg : {0.0, 135.0, 250.0}) {
    const suture::SutureState thread = endStateStitch(def, deg);
    const EndStateResult r = checkEndState(def, def.tissue.model.restPositions(), &thread);
    EXPECT_EQ(r.status, EndStateStatus::Checked);
    EXPECT_TRUE(r.findings.empty()) << deg;
    // one stitch of four holes, at its angle, its bites at their own length
    ASSERT_EQ(r.stitches.size(), 1u) << deg;
    EXPECT_EQ(r.stitches[0].holes, 4);
    EXPECT_LT(endStateApart(r.stitches[0].angleDeg, deg), 0.5) << r.stitches[0].angleDeg;
    EXPECT_NEAR(r.stitches[0].compression, 0.0, 1e-9);
    // the thread never deeper in the lumen than the faceting of the inner hull (8 µm)
    EXPECT_LT(r.deepestThreadMm, 0.01) << deg;
    EXPECT_EQ(r.largestOverlapOffsetMm, 0.0);
    EXPECT_DOUBLE_EQ(r.lumenMarginMm, 0.05);
    EXPECT_DOUBLE_EQ(r.overlapOffsetLimitMm, 0.05);
  }
}

TEST(EndStateCheck, TheInstrumentTieSceneLeftAloneShowsNoneOfTheThree) {
  Scene scene(endStateScene("instrument_tie.json"));
  for (int k = 0; k < 100; ++k) {
    InputFrame f;
    f.time = 0.01 * (k + 1);
    scene.step(f);
  }
  const EndStateResult r = checkEndState(scene);
  EXPECT_TRUE(r.findings.empty());
  ASSERT_EQ(r.stitches.size(), 1u);
  ::testing::Test::RecordProperty("stay_compression", std::to_string(r.stitches[0].compression));
  ::testing::Test::RecordProperty("stay_deepest_thread_mm", std::to_string(r.deepestThreadMm));
  EXPECT_LT(std::abs(r.stitches[0].compression), 0.02);
  EXPECT_LT(r.deepestThreadMm, 0.01);
}

TEST(EndStateCheck, TissueSqueezedInsideTheLoopIsAnOverTightStitchAtTheStitch) {
  const SceneDef def = endStateScene();
  const suture::SutureState thread = endStateStitch(def, 120.0);
  // each end's cut edge pushed back toward its clamp at the stitch: every hole's bite lies on
  // the last ring's span (0.5 mm), so its bite shortens by about twice the push
  for (const double push : {0.2, 0.05}) {
    Points x = def.tissue.model.restPositions();
    for (int end : {0, 1}) endStateBendCutRing(def, x, end, 120.0, 60.0, -push, 0.0);
    const EndStateResult r = checkEndState(def, x, &thread);
    ASSERT_EQ(r.stitches.size(), 1u);
    ::testing::Test::RecordProperty("compression_at_" + std::to_string(push),
                                    std::to_string(r.stitches[0].compression));
    EXPECT_GT(r.stitches[0].compression, 1.5 * push);
    EXPECT_LT(r.stitches[0].compression, 2.0 * push + 0.01);
    if (push < 0.1) {
      EXPECT_TRUE(r.findings.empty()) << r.stitches[0].compression;
      continue;
    }
    ASSERT_EQ(r.findings.size(), 1u);
    EXPECT_EQ(r.findings[0].kind, EndStateKind::OverTightStitch);
    EXPECT_LT(endStateApart(r.findings[0].angleDeg, 120.0), 0.5);
    EXPECT_DOUBLE_EQ(r.findings[0].measured, r.stitches[0].compression);
    EXPECT_DOUBLE_EQ(r.findings[0].limit, 0.25);
  }

  // squeezed on the other side of the vessel, the stitch is not
  Points x = def.tissue.model.restPositions();
  for (int end : {0, 1}) endStateBendCutRing(def, x, end, 300.0, 60.0, -0.2, 0.0);
  const EndStateResult away = checkEndState(def, x, &thread);
  ASSERT_EQ(away.stitches.size(), 1u);
  EXPECT_NEAR(away.stitches[0].compression, 0.0, 1e-9);
  EXPECT_TRUE(away.findings.empty());
}

TEST(EndStateCheck, ThreadInTheLumenIsFoundAtItsDeepestNodeBeyondTheMargin) {
  const SceneDef def = endStateScene();
  const CircumferenceFrame frame = endStateFrame(def);
  const suture::SutureState laid = endStateStitch(def, 0.0);
  const int last = static_cast<int>(laid.x.cols()) - 1;
  // the tail's last four nodes drawn into end 0's lumen at 90°, 0.8–1.25 mm behind its cut
  // edge (at x = −0.25), `depth` inside its inner surface (radius 0.4): the deepest the last
  for (const double depth : {0.2, 0.03}) {
    suture::SutureState thread = laid;
    for (int k = 0; k < 4; ++k)
      thread.x.col(last - k) =
          Vec3(-1.05 - 0.15 * k, 0.0, 0.0) + (0.4 - depth + 0.02 * k) * frame.direction(90.0);
    const EndStateResult r = checkEndState(def, def.tissue.model.restPositions(), &thread);
    ::testing::Test::RecordProperty("deepest_at_" + std::to_string(depth),
                                    std::to_string(r.deepestThreadMm));
    // the inner hull's faces lie up to 8 µm inside the circle through its nodes
    EXPECT_LT(r.deepestThreadMm, depth + 1e-9);
    EXPECT_GT(r.deepestThreadMm, depth - 0.01);
    if (depth < 0.05) {
      EXPECT_TRUE(r.findings.empty());
      continue;
    }
    ASSERT_EQ(r.findings.size(), 1u);
    EXPECT_EQ(r.findings[0].kind, EndStateKind::ThreadInLumen);
    EXPECT_LT(endStateApart(r.findings[0].angleDeg, 90.0), 0.5);
    EXPECT_DOUBLE_EQ(r.findings[0].measured, r.deepestThreadMm);
    EXPECT_DOUBLE_EQ(r.findings[0].limit, 0.05);
  }

  // the stitch's own crossing sagging into the lumen between its inner holes belongs there
  suture::SutureState sagging = laid;
  const int in0 = laid.pierces[1].node, in1 = laid.pierces[2].node;
  for (int k = in1 + 1; k < in0; ++k) sagging.x.col(k) -= 0.15 * frame.direction(0.0);
  const EndStateResult crossing = checkEndState(def, def.tissue.model.restPositions(), &sagging);
  EXPECT_TRUE(crossing.findings.empty());
}

TEST(EndStateCheck, ThreadAcrossOneEndsLumenIsInTheLumen) {
  const SceneDef def = endStateScene();
  // a back-wall catch's course: from end 0's inner hole at 0° the thread crosses its lumen to
  // another inner hole of end 0, at 90°, on a straight chord whose middle lies at 45°, 0.117 mm
  // inside the inner surface (0.4 − 0.4·cos 45°); its nodes split it in five, the deepest two
  // at 2/5 and 3/5 of it (34° and 56°, about 0.11 mm in)
  suture::SutureState thread = endStateStitch(def, 0.0);
  const suture::SutureState across = endStateStitch(def, 90.0);
  const int from = thread.pierces[1].node, to = thread.pierces[2].node;
  suture::Pierce caught = across.pierces[1];
  caught.node = to;
  thread.pierces[2] = caught;
  for (int k = to; k <= from; ++k) {
    const double t = static_cast<double>(from - k) / (from - to);
    thread.x.col(k) = (1.0 - t) * thread.pierces[1].point + t * caught.point;
  }
  const EndStateResult r = checkEndState(def, def.tissue.model.restPositions(), &thread);
  ASSERT_EQ(endStateCount(r, EndStateKind::ThreadInLumen), 1);
  for (const EndStateFinding& f : r.findings) {
    if (f.kind != EndStateKind::ThreadInLumen) continue;
    ::testing::Test::RecordProperty("chord_depth_mm", std::to_string(f.measured));
    ::testing::Test::RecordProperty("chord_angle_deg", std::to_string(f.angleDeg));
    EXPECT_LT(endStateApart(f.angleDeg, 45.0), 12.0) << f.angleDeg;
    EXPECT_GT(f.measured, 0.1);
    EXPECT_LT(f.measured, 0.4 - 0.4 * std::cos(std::numbers::pi / 4));
  }
}

TEST(EndStateCheck, AnEdgeRiddenOverTheOtherIsALargeOverlapWhereItRides) {
  const SceneDef def = endStateScene();
  // end 1's edge around 200° drawn a wall's thickness toward the axis and 0.6 mm toward end 0:
  // past end 0's edge by 0.1 mm, inside its lumen
  Points x = def.tissue.model.restPositions();
  endStateBendCutRing(def, x, 1, 200.0, 70.0, 0.6, 0.1);
  const EndStateResult r = checkEndState(def, x, nullptr);
  ::testing::Test::RecordProperty("overlap_offset_mm", std::to_string(r.largestOverlapOffsetMm));
  ASSERT_EQ(r.findings.size(), 1u);
  EXPECT_EQ(r.findings[0].kind, EndStateKind::LargeEdgeOverlap);
  // the largest offset at a node of the ring, within half a sector (11.25°) of the middle
  EXPECT_LT(endStateApart(r.findings[0].angleDeg, 200.0), 11.25);
  EXPECT_GT(r.findings[0].measured, 0.09);
  EXPECT_LE(r.findings[0].measured, 0.1 + 1e-9);
  EXPECT_DOUBLE_EQ(r.findings[0].measured, r.largestOverlapOffsetMm);
  EXPECT_DOUBLE_EQ(r.findings[0].limit, 0.05);

  // drawn in but not across: a step between edges still apart
  Points step = def.tissue.model.restPositions();
  endStateBendCutRing(def, step, 1, 200.0, 70.0, 0.4, 0.1);
  EXPECT_EQ(endStateCount(checkEndState(def, step, nullptr), EndStateKind::LargeEdgeOverlap), 0);
  // across but not drawn in: the edges past each other face to face, offset less than the limit
  Points level = def.tissue.model.restPositions();
  endStateBendCutRing(def, level, 1, 200.0, 70.0, 0.6, 0.03);
  const EndStateResult faceToFace = checkEndState(def, level, nullptr);
  EXPECT_GT(faceToFace.largestOverlapOffsetMm, 0.02);
  EXPECT_EQ(endStateCount(faceToFace, EndStateKind::LargeEdgeOverlap), 0);
  // and the ends drawn together whole, edge to edge, overlap nowhere
  Points apposed = def.tissue.model.restPositions();
  endStateBendCutRing(def, apposed, 1, 0.0, 1000.0, 0.49, 0.0);
  EXPECT_EQ(checkEndState(def, apposed, nullptr).largestOverlapOffsetMm, 0.0);
}

TEST(EndStateCheck, WithoutASeveredVesselThereIsNothingToCheck) {
  SceneDefLoad load = parseSceneDef(R"({"objects": [{"type": "vessel"}]})");
  ASSERT_TRUE(std::holds_alternative<SceneDef>(load));
  const SceneDef& def = std::get<SceneDef>(load);
  const EndStateResult r = checkEndState(def, def.tissue.model.restPositions(), nullptr);
  EXPECT_EQ(r.status, EndStateStatus::NoSeveredVessel);
  EXPECT_TRUE(r.findings.empty());
}

}  // namespace
}  // namespace microsim::sim
