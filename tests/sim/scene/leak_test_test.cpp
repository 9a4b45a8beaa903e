// leakTest: two vessel ends drawn together by a ring of ties, the lumen pressurised. A closed
// ring holds; a ring with a stitch left out opens where it is missing; more stitches leave a
// smaller largest gap; no pressure changes nothing.
#include "microsim/sim/scene/leak_test.h"

#include "microsim/sim/scene/scene_def.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <utility>
#include <variant>

namespace microsim::sim {
namespace {

/// The shipped anastomosis's vessel: two 16-sector ends on the x axis, 0.2 mm apart (cut back to be
/// joined), wall of 0.1 mm with the default material.
SceneDef leakTwoEnds() {
  SceneDefLoad load = parseSceneDef(
      R"({"objects": [{"type": "severed-vessel", "gap": 0.2, "axis": [1, 0, 0], "radius": 0.5,
          "wall_thickness": 0.1, "length": 3.0, "rings": 7, "nodes_per_ring": 16,
          "material": {"youngs_modulus": 3.0e5, "fung_exponent": 6, "density": 1.06e-3}}]})");
  EXPECT_TRUE(std::holds_alternative<SceneDef>(load));
  return std::get<SceneDef>(std::move(load));
}

/// 0° along +z, so that angles are easy to name: d(θ) = cos θ·z − sin θ·y about +x.
LeakTestParams leakParams(double pressureMmHg) {
  LeakTestParams p;
  p.pressureMmHg = pressureMmHg;
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
/// end, full thickness: the thread crosses the lumen between the inner pierces and is knotted
/// outside between the outer ones, so each stitch is two ties, inner and outer, each as long as
/// its two points are apart when the lips touch; `skip` names one stitch left out.
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
  const auto tied = leakTest(def, def.tissue.model.restPositions(), ties, leakParams(0.0));
  EXPECT_TRUE(tied.has_value());
  EXPECT_EQ(tied->status, LeakSolveStatus::Converged);
  return tied->x;
}

/// A ring of `count` stitches (`skip` left out) on leakTwoEnds(), tied, then pressurised to
/// 100 mmHg. Each such solve takes seconds (CTest runs every TEST as a process of its own), so
/// the tests are grouped by the rings they solve.
struct LeakRingCase {
  std::vector<LeakTie> ties;
  Points tied;
  std::optional<LeakResult> pressurised;
};
LeakRingCase leakRingAt100(const SceneDef& def, int count, int skip = -1) {
  LeakRingCase c;
  c.ties = leakRing(def, count, skip);
  c.tied = leakTied(def, c.ties);
  c.pressurised = leakTest(def, c.tied, c.ties, leakParams(100.0));
  return c;
}

/// No pressure leaves the finished line as it was.
void expectUnchangedWithoutPressure(const SceneDef& def, const LeakRingCase& ring) {
  const auto before = sutureLine(def, ring.tied, leakParams(0.0));
  const auto r = leakTest(def, ring.tied, ring.ties, leakParams(0.0));
  ASSERT_TRUE(r.has_value());
  ASSERT_EQ(r->line.size(), before.size());
  for (std::size_t i = 0; i < before.size(); ++i)
    EXPECT_NEAR(r->line[i].gapMm, before[i].gapMm, 1e-4) << before[i].angleDeg;
}

double leakLargest(const std::vector<SutureLineSample>& line) {
  double worst = 0.0;
  for (const auto& s : line) worst = std::max(worst, s.gapMm);
  return worst;
}

TEST(LeakTest, AtRestTheSutureLineIsTheScenesGapAllRound) {
  const SceneDef def = leakTwoEnds();
  const auto line = sutureLine(def, def.tissue.model.restPositions(), leakParams(0.0));
  ASSERT_EQ(line.size(), 180U);
  for (const auto& s : line) EXPECT_NEAR(s.gapMm, 0.2, 1e-12) << s.angleDeg;
}

TEST(LeakTest, AClosedRingOfEightTiesHoldsAtArterialPressureAndFourLeaveAWiderGap) {
  const SceneDef def = leakTwoEnds();
  const LeakRingCase ring = leakRingAt100(def, 8);
  // the ties drew the lips together all round, to under half the gap they had
  EXPECT_LT(leakLargest(sutureLine(def, ring.tied, leakParams(0.0))), 0.5 * 0.2);

  const auto& r = ring.pressurised;
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(r->status, LeakSolveStatus::Converged);
  EXPECT_TRUE(r->x.allFinite());
  EXPECT_TRUE(std::isfinite(r->largestGapMm));
  EXPECT_FALSE(r->leak) << r->largestGapMm << " mm at " << r->angleDeg;
  EXPECT_DOUBLE_EQ(r->thresholdMm, 0.5 * 0.1);
  EXPECT_EQ(r->slackTies, 0);
  expectUnchangedWithoutPressure(def, ring);

  // half the stitches: the lips sag further between them
  const auto& four = leakRingAt100(def, 4).pressurised;
  ASSERT_TRUE(four.has_value());
  EXPECT_GT(four->largestGapMm, r->largestGapMm);
}

TEST(LeakTest, ATieLeftOutLeaksWhereItIsMissing) {
  const SceneDef def = leakTwoEnds();
  constexpr int kMissing = 2;
  const LeakRingCase ring = leakRingAt100(def, 8, kMissing);
  const auto& r = ring.pressurised;
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(r->status, LeakSolveStatus::Converged);
  EXPECT_TRUE(r->x.allFinite());
  EXPECT_TRUE(r->leak) << r->largestGapMm << " mm at " << r->angleDeg;
  // within one tie spacing (45°) of the missing tie
  const double off = std::abs(std::remainder(r->angleDeg - 45.0 * kMissing, 360.0));
  EXPECT_LT(off, 45.0) << r->angleDeg;
  // the point is on that side of the vessel
  const double a = 45.0 * kMissing * std::numbers::pi / 180.0;
  EXPECT_GT(r->point.dot(std::cos(a) * Vec3::UnitZ() - std::sin(a) * Vec3::UnitY()), 0.0);
  expectUnchangedWithoutPressure(def, ring);
}

TEST(LeakTest, NeedsBothEndsAndFacesTheTissueHas) {
  SceneDefLoad single = parseSceneDef(R"({"objects": [{"type": "vessel"}]})");
  ASSERT_TRUE(std::holds_alternative<SceneDef>(single));
  const SceneDef& one = std::get<SceneDef>(single);
  EXPECT_FALSE(leakTest(one, one.tissue.model.restPositions(), {}).has_value());
  EXPECT_TRUE(sutureLine(one, one.tissue.model.restPositions()).empty());

  const SceneDef def = leakTwoEnds();
  LeakTie bad;
  bad.a.face = 0;
  bad.b.face = static_cast<int>(def.tissue.model.triangles().size());
  EXPECT_FALSE(leakTest(def, def.tissue.model.restPositions(), {bad}).has_value());
}

}  // namespace
}  // namespace microsim::sim
