// leakTest: two vessel ends drawn together by a ring of stitches, the lumen pressurised. A
// closed ring holds; a ring with a stitch left out opens where it is missing; fewer stitches
// leave a wider largest gap; no pressure changes nothing; the answer does not hang on the
// solver's tolerance; bad input is a status, not a crash.
#include "microsim/sim/scene/leak_test.h"

#include "microsim/sim/collide/end_gap.h"

#include "microsim/sim/scene/recording.h"
#include "microsim/sim/scene/scene.h"
#include "microsim/sim/scene/scene_def.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <utility>
#include <variant>

namespace microsim::sim {
namespace {

/// The shipped anastomosis's vessel: two 16-sector ends on the x axis, 0.2 mm apart (cut back to
/// be joined), wall of 0.1 mm with the default material.
SceneDef leakTwoEnds() {
  SceneDefLoad load = parseSceneDef(
      R"({"objects": [{"type": "severed-vessel", "gap": 0.2, "axis": [1, 0, 0], "radius": 0.5,
          "wall_thickness": 0.1, "length": 3.0, "rings": 7, "nodes_per_ring": 16,
          "material": {"youngs_modulus": 3.0e5, "fung_exponent": 6, "density": 1.06e-3}}]})");
  EXPECT_TRUE(std::holds_alternative<SceneDef>(load));
  return std::get<SceneDef>(std::move(load));
}

/// 0° along +z, so that angles are easy to name: d(θ) = cos θ·z − sin θ·y about +x.
LeakTestParams leakParams(double pressureMmHg, double tolerance = 1e-8) {
  LeakTestParams p;
  p.pressureMmHg = pressureMmHg;
  p.tolerance = tolerance;
  p.angleZero = Vec3::UnitZ();
  return p;
}

/// The point of `end`'s outer or inner surface `biteMm` back from its cut edge at angle `deg`,
/// as a face point (the nearest face whose projection holds it).
TissuePoint leakWallPoint(const SceneDef& def, int end, double deg, double biteMm,
                          VesselHull hull) {
  const SceneVessel& v = def.vessels[static_cast<std::size_t>(end)];
  const double a = deg * std::numbers::pi / 180.0;
  const Vec3 axis = v.def.direction.normalized();
  const Vec3 d = std::cos(a) * Vec3::UnitZ() - std::sin(a) * Vec3::UnitY();
  const bool outer = hull == VesselHull::Outer;
  const double radius = outer ? v.def.radius : v.def.radius - v.def.wallThickness;
  const Vec3 target = v.def.origin + (v.def.length - biteMm) * axis + radius * d;
  const TriangleRange surface = outer ? v.outerSurface : v.innerSurface;
  const auto rest = def.tissue.model.restPositions();
  TissuePoint best;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (int f = surface.begin; f < surface.end; ++f) {
    const auto& t = def.tissue.model.triangles()[static_cast<std::size_t>(f)];
    const Vec3 p0 = rest.col(t[0]), e1 = rest.col(t[1]) - p0, e2 = rest.col(t[2]) - p0;
    // barycentric of the target projected on the face's plane
    const Eigen::Matrix<double, 3, 2> e = (Eigen::Matrix<double, 3, 2>() << e1, e2).finished();
    const Eigen::Vector2d vw = (e.transpose() * e).ldlt().solve(e.transpose() * (target - p0));
    const Vec3 bary(1.0 - vw.x() - vw.y(), vw.x(), vw.y());
    const double distance = (p0 + e * vw - target).norm();
    if (bary.minCoeff() >= -1e-9 && distance < bestDistance) {
      bestDistance = distance;
      best = {f, bary};
    }
  }
  return best;
}

/// `count` stitches evenly round the line from 0°, 0.2 mm bites (two wall thicknesses) on each
/// end, full thickness: the thread crosses the gap between the inner pierces and is knotted
/// outside between the outer ones, so each stitch is two ties, inner and outer, each as long as
/// its two points are apart when the lips meet; `skip` names one stitch left out.
std::vector<LeakTie> leakRing(const SceneDef& def, int count, int skip = -1) {
  constexpr double kBite = 0.2;
  std::vector<LeakTie> ties;
  for (int i = 0; i < count; ++i) {
    if (i == skip) continue;
    const double deg = 360.0 * i / count;
    for (VesselHull hull : {VesselHull::Outer, VesselHull::Inner})
      ties.push_back({leakWallPoint(def, 0, deg, kBite, hull),
                      leakWallPoint(def, 1, deg, kBite, hull), 2.0 * kBite});
  }
  return ties;
}

/// The finished anastomosis: the ends drawn together by the ties, no pressure.
Points leakTied(const SceneDef& def, const std::vector<LeakTie>& ties) {
  const LeakResult tied = leakTest(def, def.tissue.model.restPositions(), ties, leakParams(0.0));
  EXPECT_EQ(tied.status, LeakTestStatus::Solved);
  return tied.x;
}

/// The figures the README quotes, in the test's XML or JSON output (--gtest_output).
void leakRecord(const std::string& name, const LeakResult& r) {
  ::testing::Test::RecordProperty(name + "_largest_gap_mm", std::to_string(r.largestGapMm));
  ::testing::Test::RecordProperty(name + "_angle_deg", std::to_string(r.angleDeg));
  ::testing::Test::RecordProperty(name + "_iterations", std::to_string(r.iterations));
}

double leakLargest(const std::vector<SutureLineSample>& line) {
  double worst = 0.0;
  for (const auto& s : line) worst = std::max(worst, s.gapMm);
  return worst;
}

/// Degrees between two angles, in [0, 180].
double leakAngleApart(double a, double b) {
  return std::abs(std::remainder(a - b, 360.0));
}

TEST(LeakTest, AtRestTheSutureLineIsTheScenesGapAllRound) {
  const SceneDef def = leakTwoEnds();
  const Points rest = def.tissue.model.restPositions();
  const auto line = sutureLine(def, rest, leakParams(0.0));
  ASSERT_EQ(line.size(), 180U);
  for (const auto& s : line) EXPECT_NEAR(s.gapMm, 0.2, 1e-12) << s.angleDeg;
  // the two ends' lips at one angle face each other across the gap, on both hulls
  const Vec3 axis = Vec3::UnitX();
  for (double deg : {0.0, 10.0, 100.0, 215.0}) {
    const double a = deg * std::numbers::pi / 180.0;
    const Vec3 d = std::cos(a) * Vec3::UnitZ() - std::sin(a) * Vec3::UnitY();
    for (VesselHull hull : {VesselHull::Outer, VesselHull::Inner}) {
      const Vec3 lip0 = collide::cutRingLip(def.tissue.model, rest, def.vessels[0], d, hull);
      const Vec3 lip1 = collide::cutRingLip(def.tissue.model, rest, def.vessels[1], d, hull);
      EXPECT_NEAR((lip1 - lip0).norm(), 0.2, 1e-12) << deg;
      EXPECT_NEAR((lip1 - lip0).dot(axis), 0.2, 1e-12) << deg;
    }
  }
}

TEST(LeakTest, AClosedRingOfEightStitchesHoldsAtArterialPressure) {
  const SceneDef def = leakTwoEnds();
  const auto ties = leakRing(def, 8);
  const LeakResult r = leakTest(def, leakTied(def, ties), ties, leakParams(100.0));
  leakRecord("eight", r);
  EXPECT_EQ(r.status, LeakTestStatus::Solved);
  EXPECT_LE(r.iterations, 30);
  EXPECT_TRUE(r.x.allFinite());
  EXPECT_DOUBLE_EQ(r.thresholdMm, 0.5 * 0.1);
  EXPECT_DOUBLE_EQ(r.pressureMmHg, 100.0);
  EXPECT_EQ(r.line.size(), 180U);
  // measured: 0.034 mm, between two stitches
  EXPECT_FALSE(r.leak) << r.largestGapMm << " mm at " << r.angleDeg;
  EXPECT_GT(r.largestGapMm, 0.02);
  EXPECT_LT(r.largestGapMm, r.thresholdMm);
}

TEST(LeakTest, AStitchLeftOutLeaksWhereItIsMissing) {
  const SceneDef def = leakTwoEnds();
  for (int missing : {2, 5}) {
    const auto ties = leakRing(def, 8, missing);
    const LeakResult r = leakTest(def, leakTied(def, ties), ties, leakParams(100.0));
    leakRecord("seven_without_" + std::to_string(missing), r);
    EXPECT_EQ(r.status, LeakTestStatus::Solved);
    EXPECT_LE(r.iterations, 30);
    // measured: 0.108 mm at the missing stitch's own angle
    EXPECT_TRUE(r.leak) << r.largestGapMm << " mm at " << r.angleDeg;
    EXPECT_GT(r.largestGapMm, 2.0 * r.thresholdMm);
    // within one stitch spacing (45°) of the missing stitch
    EXPECT_LT(leakAngleApart(r.angleDeg, 45.0 * missing), 45.0) << r.angleDeg;
  }
}

TEST(LeakTest, FourStitchesLeaveAWiderLargestGapThanEight) {
  const SceneDef def = leakTwoEnds();
  const auto eight = leakRing(def, 8);
  const auto four = leakRing(def, 4);
  const LeakResult r8 = leakTest(def, leakTied(def, eight), eight, leakParams(100.0));
  const LeakResult r4 = leakTest(def, leakTied(def, four), four, leakParams(100.0));
  leakRecord("four", r4);
  ASSERT_EQ(r8.status, LeakTestStatus::Solved);
  ASSERT_EQ(r4.status, LeakTestStatus::Solved);
  EXPECT_LE(r4.iterations, 30);
  // measured: 0.112 mm against 0.034 mm
  EXPECT_GT(r4.largestGapMm, 2.0 * r8.largestGapMm);
  EXPECT_TRUE(r4.leak);
}

TEST(LeakTest, NoPressureChangesNothing) {
  const SceneDef def = leakTwoEnds();
  for (int missing : {-1, 3}) {
    const auto ties = leakRing(def, 8, missing);
    const Points tied = leakTied(def, ties);
    const auto before = sutureLine(def, tied, leakParams(0.0));
    const LeakResult r = leakTest(def, tied, ties, leakParams(0.0));
    EXPECT_EQ(r.status, LeakTestStatus::Solved);
    EXPECT_EQ(r.iterations, 0);
    EXPECT_EQ(r.x, tied);
    ASSERT_EQ(r.line.size(), before.size());
    for (std::size_t i = 0; i < before.size(); ++i) EXPECT_EQ(r.line[i].gapMm, before[i].gapMm);
    EXPECT_EQ(r.largestGapMm, leakLargest(before));
  }
}

TEST(LeakTest, TheVerdictAndTheGapDoNotHangOnTheSolversTolerance) {
  const SceneDef def = leakTwoEnds();
  for (const auto& [count, missing] : {std::pair{8, -1}, std::pair{8, 2}, std::pair{4, -1}}) {
    SCOPED_TRACE(::testing::Message() << count << " stitches, " << missing << " left out");
    const auto ties = leakRing(def, count, missing);
    const Points tied = leakTied(def, ties);
    const LeakResult loose = leakTest(def, tied, ties, leakParams(100.0, 1e-8));
    const LeakResult tight = leakTest(def, tied, ties, leakParams(100.0, 1e-10));
    ASSERT_EQ(loose.status, LeakTestStatus::Solved);
    ASSERT_EQ(tight.status, LeakTestStatus::Solved);
    EXPECT_LE(tight.iterations, 30);
    EXPECT_EQ(loose.leak, tight.leak);
    EXPECT_NEAR(loose.largestGapMm, tight.largestGapMm, 1e-3);
  }
}

TEST(LeakTest, BadInputIsAStatusNotACrash) {
  // a single vessel: no suture line
  SceneDefLoad single = parseSceneDef(R"({"objects": [{"type": "vessel"}]})");
  ASSERT_TRUE(std::holds_alternative<SceneDef>(single));
  const SceneDef& one = std::get<SceneDef>(single);
  const LeakResult lone = leakTest(one, one.tissue.model.restPositions(), {});
  EXPECT_EQ(lone.status, LeakTestStatus::NoSeveredVessel);
  EXPECT_FALSE(lone.leak);
  EXPECT_TRUE(std::isnan(lone.largestGapMm));
  EXPECT_TRUE(lone.line.empty());
  EXPECT_TRUE(sutureLine(one, one.tissue.model.restPositions()).empty());

  // two ends and no stitch
  const SceneDef def = leakTwoEnds();
  const Points rest = def.tissue.model.restPositions();
  const LeakResult open = leakTest(def, rest, {});
  EXPECT_EQ(open.status, LeakTestStatus::NoStitches);
  EXPECT_FALSE(open.leak);
  EXPECT_TRUE(std::isnan(open.largestGapMm));

  // a tie on a face the tissue does not have
  LeakTie bad;
  bad.a.face = 0;
  bad.b.face = static_cast<int>(def.tissue.model.triangles().size());
  EXPECT_EQ(leakTest(def, rest, {bad}).status, LeakTestStatus::BadTie);

  // a position that is not a number
  Points broken = rest;
  broken(0, 40) = std::numeric_limits<double>::quiet_NaN();
  const LeakResult nan = leakTest(def, broken, leakRing(def, 8), leakParams(100.0));
  EXPECT_EQ(nan.status, LeakTestStatus::SolverFailed);
  EXPECT_FALSE(nan.leak);
  EXPECT_TRUE(std::isnan(nan.largestGapMm));
}

// The shipped stitch (one stitch, no knot) replayed on the shipped scene: its one tie holds the
// ends at one point of a 0.5 mm gap, so the line leaks; the test leaves the scene as it was.
TEST(LeakTest, TheShippedStitchLeaksWithoutChangingTheScene) {
  const std::string root = MICROSIM_SOURCE_DIR;
  SceneDefLoad load = loadSceneDef(root + "/resources/scenes/anastomosis.json");
  ASSERT_TRUE(std::holds_alternative<SceneDef>(load));
  Recording rec;
  ASSERT_TRUE(readRecording(root + "/resources/recordings/stitch.msrec", rec).ok());
  Scene scene(std::get<SceneDef>(load), StepMode::Deterministic);
  for (const InputFrame& f : rec.frames) scene.step(f);
  const std::uint64_t hash = scene.hash();

  const std::vector<LeakTie> ties = sutureTies(scene);
  ASSERT_EQ(ties.size(), 1U);
  const LeakResult r = leakTest(scene);
  leakRecord("shipped", r);
  EXPECT_EQ(r.status, LeakTestStatus::Solved);
  // measured: 29 iterations, the ends (each buckling under the thrust where the stitch does
  // not hold it) 2.29 mm apart at 190°, opposite the stitch
  EXPECT_LE(r.iterations, 40);
  EXPECT_TRUE(r.leak) << r.largestGapMm << " mm at " << r.angleDeg;
  EXPECT_GT(r.largestGapMm, 0.5);
  EXPECT_GT(leakAngleApart(r.angleDeg, 0.0), 135.0) << r.angleDeg;
  EXPECT_EQ(scene.hash(), hash);
}

}  // namespace
}  // namespace microsim::sim
