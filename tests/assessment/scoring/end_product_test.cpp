// The finished anastomosis judged on hand-made stitches around one severed vessel: a clean ring
// has no error, each lapse is found at its stitch, passage and angle, a hole the thread never
// reached is not judged, events and a leak are disruptions and tears, the final scene's
// over-tight stitches, thread in the lumen and edge overlaps (sim/scene/end_state_check.h) are
// reported where the check found them, the metric keys count them, and the shipped stitch (one
// clean stitch) shows none.
#include "microsim/assessment/scoring/end_product.h"
#include "microsim/assessment/scoring/metrics.h"

#include "microsim/sim/scene/scene_def.h"

#include "support/severed_vessel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>
#include <string>
#include <variant>

namespace {

using namespace microsim::assessment;
using microsim::sim::PierceEvent;
using microsim::sim::SceneEvent;
using microsim::sim::SceneEventKind;
using microsim::sim::Vec3;
using microsim::sim::VesselSurface;
using microsim::sim::VesselWall;

using microsim::testing::kSeveredVesselRadius;
using microsim::testing::severedVessel;

const std::string kEndProductRoot = MICROSIM_SOURCE_DIR;

// a point on end `end`'s outer surface at `deg` around (0° up, +90° toward −y)
Vec3 aroundEnd(int end, double deg) {
  const double rad = deg * std::numbers::pi / 180.0;
  return {end == 0 ? -0.5 : 0.5, -kSeveredVesselRadius * std::sin(rad),
          kSeveredVesselRadius * std::cos(rad)};
}

// one wall passage: in through `in`, out through `out`
void addPassage(Attempt& a, int end, double deg, double biteMm, VesselSurface in, VesselSurface out,
                VesselWall wall = VesselWall::Front) {
  for (const bool entry : {true, false}) {
    PierceEvent p;
    p.entry = entry;
    p.vessel = end;
    p.end = end;
    p.surface = entry ? in : out;
    p.wall = wall;
    p.biteMm = biteMm;
    p.point = aroundEnd(end, deg);
    a.pierces.push_back(p);
  }
}

// a stitch outside-in through end 0 at `degA`, inside-out through end 1 at `degB`
void addStitch(Attempt& a, double degA, double degB, double biteA = 0.25, double biteB = 0.25) {
  addPassage(a, 0, degA, biteA, VesselSurface::Outer, VesselSurface::Inner);
  addPassage(a, 1, degB, biteB, VesselSurface::Inner, VesselSurface::Outer);
}

// eight stitches 45° apart, each bite 2.5 wall thicknesses, parallel to the axis
Attempt cleanRing() {
  Attempt a = severedVessel();
  for (int s = 0; s < 8; ++s) addStitch(a, 45.0 * s, 45.0 * s);
  return a;
}

SceneEvent endProductEvent(SceneEventKind kind, int index, int count = 1) {
  SceneEvent e;
  e.kind = kind;
  e.index = index;
  e.count = count;
  return e;
}

TEST(EndProduct, ACleanRingOfStitchesHasNoErrors) {
  const Attempt a = cleanRing();
  EXPECT_TRUE(endProductErrors(a).empty());
  const AttemptMetrics m = computeMetrics(a);
  EXPECT_EQ(m.stitches.size(), 8u);
  for (const char* key : {"lapse_index", "oblique_stitches", "partial_thickness_bites",
                          "wide_bites", "unequal_spacing"})
    EXPECT_EQ(m.value(key), 0.0) << key;
}

TEST(EndProduct, BackWallAndPartialThicknessPassagesAreFoundAtTheirStitchAndAngle) {
  Attempt a = severedVessel();
  addStitch(a, 0.0, 0.0);
  addStitch(a, 90.0, 90.0);
  // stitch 2: its second bite goes in and out of the inner surface
  addPassage(a, 0, 180.0, 0.25, VesselSurface::Outer, VesselSurface::Inner);
  addPassage(a, 1, 180.0, 0.25, VesselSurface::Inner, VesselSurface::Inner);
  // stitch 3: its first bite enters the back wall
  addPassage(a, 0, 270.0, 0.25, VesselSurface::Outer, VesselSurface::Inner, VesselWall::Back);
  addPassage(a, 1, 270.0, 0.25, VesselSurface::Inner, VesselSurface::Outer);

  const std::vector<EndProductError> errors = endProductErrors(a);
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_EQ(errors[0].kind, EndProductErrorKind::PartialThicknessBite);
  EXPECT_EQ(errors[0].stitch, 2);
  EXPECT_EQ(errors[0].passage, 5);
  EXPECT_NEAR(errors[0].angleDeg, 180.0, 1e-9);
  EXPECT_TRUE(std::isnan(errors[0].measured));
  EXPECT_EQ(errors[1].kind, EndProductErrorKind::BackWallStitch);
  EXPECT_EQ(errors[1].stitch, 3);
  EXPECT_EQ(errors[1].passage, 6);
  EXPECT_NEAR(errors[1].angleDeg, 270.0, 1e-9);
  EXPECT_EQ(errors[1].event, -1);
  EXPECT_EQ(computeMetrics(a).value("partial_thickness_bites"), 1.0);
  EXPECT_EQ(computeMetrics(a).value("lapse_index"), 2.0);
}

TEST(EndProduct, ABiteBeyondThreeWallThicknessesIsWide) {
  Attempt a = cleanRing();
  a.pierces[12].biteMm = 0.4;  // stitch 3's first passage (entry), 4 walls
  const std::vector<EndProductError> errors = endProductErrors(a);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].kind, EndProductErrorKind::WideBite);
  EXPECT_EQ(errors[0].stitch, 3);
  EXPECT_EQ(errors[0].passage, 6);
  EXPECT_NEAR(errors[0].angleDeg, 135.0, 1e-9);
  EXPECT_NEAR(errors[0].measured, 4.0, 1e-12);
  EXPECT_DOUBLE_EQ(errors[0].limit, 3.0);
  EXPECT_EQ(computeMetrics(a).value("wide_bites"), 1.0);

  // the limit is the caller's
  EndProductLimits longer;
  longer.wideBiteWalls = 4.5;
  EXPECT_TRUE(endProductErrors(a, std::nullopt, longer).empty());
}

TEST(EndProduct, AStitchWhoseBitesLieApartAroundTheWallIsOblique) {
  Attempt a = severedVessel();
  for (int s = 0; s < 8; ++s) addStitch(a, 45.0 * s, 45.0 * s + (s == 5 ? 20.0 : 10.0));
  const std::vector<EndProductError> errors = endProductErrors(a);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].kind, EndProductErrorKind::ObliqueStitch);
  EXPECT_EQ(errors[0].stitch, 5);
  EXPECT_EQ(errors[0].passage, -1);
  EXPECT_NEAR(errors[0].angleDeg, 235.0, 1e-9);  // the stitch's middle
  EXPECT_NEAR(errors[0].measured, 20.0, 1e-9);
  EXPECT_DOUBLE_EQ(errors[0].limit, 15.0);
  EXPECT_EQ(computeMetrics(a).value("oblique_stitches"), 1.0);

  // across 0°: 350° and 10° are 20° apart
  Attempt across = severedVessel();
  addStitch(across, 350.0, 10.0);
  ASSERT_EQ(endProductErrors(across).size(), 1u);
  EXPECT_NEAR(endProductErrors(across)[0].measured, 20.0, 1e-9);
  EXPECT_NEAR(std::fmod(endProductErrors(across)[0].angleDeg + 180.0, 360.0), 180.0, 1e-9);
}

TEST(EndProduct, UnequalSpacingIsTheGapBetweenNeighboursAroundTheCircle) {
  // placed as triangulation places them: 0°, 180°, then 90° and 200°; the mean gap is 90°
  Attempt a = severedVessel();
  for (double deg : {0.0, 180.0, 90.0, 200.0}) addStitch(a, deg, deg);
  const std::vector<EndProductError> errors = endProductErrors(a);
  ASSERT_EQ(errors.size(), 2u);
  // 180° → 200°: 20° where 90° is the mean
  EXPECT_EQ(errors[0].kind, EndProductErrorKind::UnequalSpacing);
  EXPECT_EQ(errors[0].stitch, 1);
  EXPECT_NEAR(errors[0].angleDeg, 190.0, 1e-9);
  EXPECT_NEAR(errors[0].measured, 70.0 / 90.0, 1e-9);
  EXPECT_DOUBLE_EQ(errors[0].limit, 0.5);
  // 200° → 360°: 160°, the gap across 0°
  EXPECT_EQ(errors[1].stitch, 3);
  EXPECT_NEAR(errors[1].angleDeg, 280.0, 1e-9);
  EXPECT_NEAR(errors[1].measured, 70.0 / 90.0, 1e-9);
  EXPECT_EQ(computeMetrics(a).value("unequal_spacing"), 2.0);

  // two stitches have no spacing to judge
  Attempt two = severedVessel();
  addStitch(two, 0.0, 0.0);
  addStitch(two, 30.0, 30.0);
  EXPECT_TRUE(endProductErrors(two).empty());
}

TEST(EndProduct, AHoleTheThreadNeverReachedIsNotJudged) {
  Attempt a = cleanRing();
  // a bite drawn back out of the outer surface before stitch 0, at 20°
  Attempt withdrawn = severedVessel();
  addPassage(withdrawn, 0, 20.0, 0.45, VesselSurface::Outer, VesselSurface::Outer);
  withdrawn.pierces.insert(withdrawn.pierces.end(), a.pierces.begin(), a.pierces.end());
  withdrawn.events.push_back(endProductEvent(SceneEventKind::PierceReleased, 0));
  EXPECT_TRUE(endProductErrors(withdrawn).empty());

  // left in, it is a partial and wide bite outside any stitch
  withdrawn.events.clear();
  const std::vector<EndProductError> errors = endProductErrors(withdrawn);
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_EQ(errors[0].kind, EndProductErrorKind::PartialThicknessBite);
  EXPECT_EQ(errors[1].kind, EndProductErrorKind::WideBite);
  for (const EndProductError& e : errors) {
    EXPECT_EQ(e.passage, 0);
    EXPECT_EQ(e.stitch, -1);
    EXPECT_NEAR(e.angleDeg, 20.0, 1e-9);
  }
}

TEST(EndProduct, TearsBreaksPullOutsAndALeakAreReportedInEventOrder) {
  Attempt a = cleanRing();
  a.events = {
      endProductEvent(SceneEventKind::GrabTissue, 3),
      endProductEvent(SceneEventKind::TissueTear, 40, 3),
      endProductEvent(SceneEventKind::SutureBreak, 12),
      endProductEvent(SceneEventKind::SuturePulledOut, 9)};  // the exit of stitch 2's first bite
  LeakFinding leak;
  leak.leaks = true;
  leak.largestGapMm = 0.12;
  leak.angleDeg = 300.0;
  const std::vector<EndProductError> errors = endProductErrors(a, leak);
  ASSERT_EQ(errors.size(), 4u);

  // the tear: how many links, not located
  EXPECT_EQ(errors[0].kind, EndProductErrorKind::WallTear);
  EXPECT_EQ(errors[0].event, 1);
  EXPECT_DOUBLE_EQ(errors[0].measured, 3.0);
  EXPECT_TRUE(std::isnan(errors[0].angleDeg));
  // the break: the thread is gone, not located
  EXPECT_EQ(errors[1].kind, EndProductErrorKind::SutureLineDisruption);
  EXPECT_EQ(errors[1].event, 2);
  EXPECT_EQ(errors[1].stitch, -1);
  EXPECT_TRUE(std::isnan(errors[1].angleDeg));
  // pulled out of pierce 9, the exit of passage 4: stitch 2 at 90°
  EXPECT_EQ(errors[2].kind, EndProductErrorKind::SutureLineDisruption);
  EXPECT_EQ(errors[2].event, 3);
  EXPECT_EQ(errors[2].passage, 4);
  EXPECT_EQ(errors[2].stitch, 2);
  EXPECT_NEAR(errors[2].angleDeg, 90.0, 1e-9);
  // the leak at its largest gap
  EXPECT_EQ(errors[3].kind, EndProductErrorKind::SutureLineDisruption);
  EXPECT_EQ(errors[3].event, -1);
  EXPECT_DOUBLE_EQ(errors[3].angleDeg, 300.0);
  EXPECT_DOUBLE_EQ(errors[3].measured, 0.12);

  // a line that holds its pressure adds nothing
  leak.leaks = false;
  EXPECT_EQ(endProductErrors(a, leak).size(), 3u);
  // the metrics have no leak test
  EXPECT_EQ(computeMetrics(a).value("lapse_index"), 3.0);
}

TEST(EndProduct, EveryKindHasItsOwnStableKey) {
  std::set<std::string> keys;
  for (const EndProductErrorKind kind : endProductErrorKinds())
    keys.insert(std::string(endProductErrorKey(kind)));
  EXPECT_EQ(keys.size(), 10u);
  EXPECT_EQ(endProductErrorKey(EndProductErrorKind::SutureLineDisruption),
            "suture_line_disruption");
  EXPECT_EQ(endProductErrorKey(EndProductErrorKind::LargeEdgeOverlap), "large_edge_overlap");
  EXPECT_EQ(endProductErrorUnit(EndProductErrorKind::WideBite), "walls");
  EXPECT_EQ(endProductErrorUnit(EndProductErrorKind::BackWallStitch), "");
  EXPECT_EQ(endProductErrorUnit(EndProductErrorKind::OverTightStitch), "1");
  EXPECT_EQ(endProductErrorUnit(EndProductErrorKind::ThreadInLumen), "mm");
  EXPECT_EQ(endProductErrorUnit(EndProductErrorKind::LargeEdgeOverlap), "mm");
}

TEST(EndProduct, TheFinalScenesLapsesComeAfterTheEventsBeforeTheLeak) {
  Attempt a = cleanRing();
  a.events = {endProductEvent(SceneEventKind::SutureBreak, 12)};
  microsim::sim::EndStateResult end;
  using microsim::sim::EndStateKind;
  end.findings = {{EndStateKind::OverTightStitch, 45.0, 0.4, 0.25},
                  {EndStateKind::ThreadInLumen, 100.0, 0.2, 0.05},
                  {EndStateKind::LargeEdgeOverlap, 210.0, 0.09, 0.05}};
  a.endState = end;
  LeakFinding leak;
  leak.leaks = true;
  leak.angleDeg = 300.0;
  const std::vector<EndProductError> errors = endProductErrors(a, leak);
  ASSERT_EQ(errors.size(), 5u);
  EXPECT_EQ(errors[0].kind, EndProductErrorKind::SutureLineDisruption);
  EXPECT_EQ(errors[0].event, 0);
  const EndProductErrorKind kinds[3] = {EndProductErrorKind::OverTightStitch,
                                        EndProductErrorKind::ThreadInLumen,
                                        EndProductErrorKind::LargeEdgeOverlap};
  for (std::size_t k = 0; k < 3; ++k) {
    const EndProductError& e = errors[k + 1];
    EXPECT_EQ(e.kind, kinds[k]) << k;
    EXPECT_DOUBLE_EQ(e.angleDeg, end.findings[k].angleDeg);
    EXPECT_DOUBLE_EQ(e.measured, end.findings[k].measured);
    EXPECT_DOUBLE_EQ(e.limit, end.findings[k].limit);
    EXPECT_EQ(e.stitch, -1);
    EXPECT_EQ(e.passage, -1);
    EXPECT_EQ(e.event, -1);
  }
  EXPECT_DOUBLE_EQ(errors[4].angleDeg, 300.0);
  // counted in the lapse index, unlike the leak
  EXPECT_EQ(computeMetrics(a).value("lapse_index"), 4.0);
  // a final scene that showed nothing, or none looked at, adds nothing
  a.endState = microsim::sim::EndStateResult{};
  EXPECT_EQ(endProductErrors(a).size(), 1u);
  a.endState.reset();
  EXPECT_EQ(endProductErrors(a).size(), 1u);
}

TEST(EndProduct, AnEdgeRiddenOverTheOtherInTheShippedSceneIsALargeOverlapThere) {
  microsim::sim::SceneDefLoad load =
      microsim::sim::loadSceneDef(kEndProductRoot + "/resources/scenes/anastomosis.json");
  ASSERT_TRUE(std::holds_alternative<microsim::sim::SceneDef>(load));
  const microsim::sim::SceneDef& def = std::get<microsim::sim::SceneDef>(load);
  Attempt a = assembleAttempt(def, {}, {}, {}, 0.0);
  // end 1's cut edge from 90° to 180° drawn a wall's thickness in and 0.6 mm across end 0's
  const auto& end1 = def.vessels[1];
  const int p = end1.def.nodesPerRing;
  microsim::sim::Points x = def.tissue.model.restPositions();
  const VesselGeometry& g = a.vessels[0];
  for (int hull = 0; hull < 2; ++hull)
    for (int j = 0; j < p; ++j) {
      const int node = end1.firstNode + ((end1.def.rings - 1) * 2 + hull) * p + j;
      if (!(std::abs(std::remainder(circumferentialAngleDeg(g, x.col(node)) - 135.0, 360.0)) <=
            45.0))
        continue;
      Vec3 radial = x.col(node) - end1.def.origin;
      radial.x() = 0.0;
      x.col(node) += Vec3(-0.6, 0.0, 0.0) - 0.1 * radial.normalized();
    }
  a.endState = microsim::sim::checkEndState(def, x, nullptr);
  const std::vector<EndProductError> errors = endProductErrors(a);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].kind, EndProductErrorKind::LargeEdgeOverlap);
  // where it rides, in the pierces' angles, and by a wall's thickness against half of one
  EXPECT_GE(errors[0].angleDeg, 90.0);
  EXPECT_LE(errors[0].angleDeg, 180.0);
  EXPECT_NEAR(errors[0].measured, 0.1, 0.01);
  EXPECT_DOUBLE_EQ(errors[0].limit, 0.05);
}

TEST(EndProduct, TheShippedStitchIsOneStitchWithoutALapse) {
  auto replayed = replayAttempt(kEndProductRoot + "/resources/scenes/anastomosis.json",
                                kEndProductRoot + "/resources/recordings/stitch.msrec");
  ASSERT_TRUE(std::holds_alternative<Attempt>(replayed));
  const Attempt& a = std::get<Attempt>(replayed);
  // one stitch: both bites full thickness through the front wall at 359.9°, 2.5 and 0.93 wall
  // thicknesses long, nothing torn, broken or pulled out; so no lapse
  const std::vector<PierceMetrics> passages = pierceMetrics(a);
  ASSERT_EQ(passages.size(), 2u);
  for (const PierceMetrics& p : passages) {
    EXPECT_TRUE(p.fullThickness);
    EXPECT_FALSE(p.backWall);
    EXPECT_LT(p.biteWalls, 3.0);
  }
  EXPECT_LT(angularDistanceDeg(passages[0].circumferenceDeg, passages[1].circumferenceDeg), 1.0);
  EXPECT_TRUE(endProductErrors(a).empty());
  // the final scene looked at, and clean: no stitch squeezed, no thread in the lumen, the
  // edges nowhere past each other
  ASSERT_TRUE(a.endState.has_value());
  EXPECT_EQ(a.endState->status, microsim::sim::EndStateStatus::Checked);
  EXPECT_TRUE(a.endState->findings.empty());
  for (const microsim::sim::StitchCompression& s : a.endState->stitches) {
    ::testing::Test::RecordProperty("shipped_compression", std::to_string(s.compression));
    EXPECT_LT(s.compression, 0.25);
  }
  ::testing::Test::RecordProperty("shipped_deepest_thread_mm",
                                  std::to_string(a.endState->deepestThreadMm));
  ::testing::Test::RecordProperty("shipped_overlap_offset_mm",
                                  std::to_string(a.endState->largestOverlapOffsetMm));

  // a stricter examiner's bite limit finds the first bite, where it is
  EndProductLimits strict;
  strict.wideBiteWalls = 2.0;
  const std::vector<EndProductError> errors = endProductErrors(a, std::nullopt, strict);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].kind, EndProductErrorKind::WideBite);
  EXPECT_EQ(errors[0].stitch, 0);
  EXPECT_EQ(errors[0].passage, 0);
  EXPECT_NEAR(errors[0].angleDeg, passages[0].circumferenceDeg, 1e-12);
  EXPECT_NEAR(errors[0].measured, passages[0].biteWalls, 1e-12);
}

}  // namespace
