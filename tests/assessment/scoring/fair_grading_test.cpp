// Grading that does not punish the input device and that checks the needle's arc: stepped
// (keyboard) motion gets smoothness and idle time "not applicable" and weighted out, a needle
// swept sideways through the lumen fails lesson 2, and extra wall passages cost points.
#include "microsim/assessment/scoring/arc_metrics.h"
#include "microsim/assessment/scoring/metrics.h"
#include "microsim/assessment/scoring/motion_metrics.h"
#include "microsim/assessment/scoring/rubric.h"
#include "microsim/assessment/scoring/score.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace {

using namespace microsim::assessment;
namespace sim = microsim::sim;
using sim::Vec3;

constexpr double kNeedleRadius = 0.8;  // resources/scenes/anastomosis.json
const Vec3 kArcCentre(0.0, -0.09, 1.104);

// the tip of a needle turned about its arc's centre, in the x–z plane, at angle φ
Vec3 tipOnArc(double phi) {
  return kArcCentre + kNeedleRadius * Vec3(std::cos(phi), 0.0, std::sin(phi));
}
Vec3 tangentOnArc(double phi) { return Vec3(-std::sin(phi), 0.0, std::cos(phi)); }

sim::PierceEvent wallCrossing(double time, bool entry, int end, sim::VesselSurface surface,
                              const Vec3& point, const Vec3& tangent) {
  sim::PierceEvent p;
  p.time = time;
  p.entry = entry;
  p.point = point;
  p.restPoint = point;
  p.tangent = tangent;
  p.angleDeg = 10.0;
  p.vessel = end;
  p.end = end;
  p.surface = surface;
  p.biteMm = 0.25;  // 2.5 wall thicknesses
  return p;
}

// Lesson 2's pass through the near end's wall and out of the far end's: four crossings at
// the angles the arc meets the outer (z 0.48) and inner (z 0.38) surfaces, from `start` s
std::vector<sim::PierceEvent> passAlongTheArc(double start) {
  using S = sim::VesselSurface;
  const double outer = std::asin((0.48 - kArcCentre.z()) / kNeedleRadius);  // −0.89 rad
  const double inner = std::asin((0.38 - kArcCentre.z()) / kNeedleRadius);  // −1.13 rad
  const std::array<double, 4> phi{-M_PI - outer, -M_PI - inner, inner, outer};
  return {wallCrossing(start + 0.0, true, 0, S::Outer, tipOnArc(phi[0]), tangentOnArc(phi[0])),
          wallCrossing(start + 0.2, false, 0, S::Inner, tipOnArc(phi[1]), tangentOnArc(phi[1])),
          wallCrossing(start + 0.6, true, 1, S::Inner, tipOnArc(phi[2]), tangentOnArc(phi[2])),
          wallCrossing(start + 0.8, false, 1, S::Outer, tipOnArc(phi[3]), tangentOnArc(phi[3]))};
}

Attempt lessonTwoAttempt(std::vector<sim::PierceEvent> pierces) {
  Attempt a;
  a.pierces = std::move(pierces);
  a.needleRadius = kNeedleRadius;
  a.duration = 30.0;
  a.steps = 3000;
  for (int end = 0; end < 2; ++end) {
    VesselGeometry v;
    v.vessel = end;
    v.object = 0;
    v.end = end;
    v.wallThickness = 0.1;
    a.vessels.push_back(v);
  }
  return a;
}

Rubric shippedRubric(const std::string& name) {
  auto r = loadRubric(std::string(MICROSIM_SOURCE_DIR) + "/resources/rubrics/" + name + ".json");
  EXPECT_TRUE(std::holds_alternative<Rubric>(r));
  return std::get<Rubric>(std::move(r));
}

TEST(ArcDeviation, IsZeroAlongTheArcAndTheWholeDisplacementWithoutATurn) {
  EXPECT_NEAR(arcDeviationMm(tipOnArc(-2.0), tangentOnArc(-2.0), tipOnArc(-1.0),
                             tangentOnArc(-1.0), kNeedleRadius),
              0.0, 1e-12);
  // pushed straight 0.3 mm and swept 1 mm sideways without turning
  const Vec3 down(0.0, 0.0, -1.0);
  EXPECT_NEAR(arcDeviationMm(Vec3::Zero(), down, Vec3(0, 0, -0.3), down, kNeedleRadius), 0.3,
              1e-12);
  EXPECT_NEAR(arcDeviationMm(Vec3::Zero(), down, Vec3(1.0, 0, 0), down, kNeedleRadius), 1.0,
              1e-12);
  // a curved needle of the wrong radius (turned about another centre) is off its arc too
  EXPECT_GT(arcDeviationMm(tipOnArc(-2.0), tangentOnArc(-2.0), tipOnArc(-1.0),
                           tangentOnArc(-1.0), 2.0 * kNeedleRadius),
            0.5);
}

TEST(FairGrading, TheSidewaysSweepThroughTheLumenDoesNotPassLessonTwo) {
  const Rubric rubric = shippedRubric("02_needle_entry");
  const Attempt clean = lessonTwoAttempt(passAlongTheArc(1.0));

  // straight in at the first mark, 1 mm sideways through the lumen, out at the second: the
  // needle never turned
  std::vector<sim::PierceEvent> swept = passAlongTheArc(1.0);
  const std::array<double, 4> x{-0.5, -0.5, 0.5, 0.5};
  const std::array<double, 4> z{0.48, 0.38, 0.38, 0.48};
  for (std::size_t i = 0; i < swept.size(); ++i) {
    swept[i].point = swept[i].restPoint = Vec3(x[i], kArcCentre.y(), z[i]);
    swept[i].tangent = Vec3(0.0, 0.0, -1.0);
  }
  const Attempt sweep = lessonTwoAttempt(swept);

  const AttemptScore cleanScore = scoreAttempt(clean, rubric);
  const AttemptScore sweepScore = scoreAttempt(sweep, rubric);
  EXPECT_NEAR(computeMetrics(clean).value("arc_deviation").value(), 0.0, 1e-9);
  EXPECT_NEAR(computeMetrics(sweep).value("arc_deviation").value(), 1.0, 1e-9);
  EXPECT_TRUE(cleanScore.passed) << cleanScore.score;
  EXPECT_FALSE(sweepScore.passed) << sweepScore.score;
  EXPECT_LE(sweepScore.score, 50.0);
  EXPECT_EQ(sweepScore.neverEvents, std::vector<std::string>{"never.needle_dragged"});
}

TEST(FairGrading, FourPassagesScoreBelowOneCleanPassage) {
  const Rubric rubric = shippedRubric("02_needle_entry");
  const Attempt clean = lessonTwoAttempt(passAlongTheArc(1.0));

  // the same pass done twice, the needle re-gripped in between: every crossing on its arc
  std::vector<sim::PierceEvent> twice = passAlongTheArc(1.0);
  for (const sim::PierceEvent& p : passAlongTheArc(3.0)) twice.push_back(p);
  Attempt again = lessonTwoAttempt(twice);
  sim::SceneEvent regrip;
  regrip.kind = sim::SceneEventKind::GripSuture;
  regrip.time = 2.5;
  regrip.hand = 1;
  again.events.push_back(regrip);

  const AttemptMetrics metrics = computeMetrics(again);
  EXPECT_DOUBLE_EQ(metrics.value("passages").value(), 4.0);
  EXPECT_NEAR(metrics.value("arc_deviation").value(), 0.0, 1e-9);
  const double cleanScore = scoreAttempt(clean, rubric).score;
  const AttemptScore fourScore = scoreAttempt(again, rubric);
  EXPECT_LT(fourScore.score, cleanScore);
  EXPECT_EQ(fourScore.metrics.front().feedback, "pierce.extra_passages");
}

// one hand moving as the keyboard moves it: a 0.05 mm jump every third step, still between
Attempt keyboardAttempt() {
  Attempt a;
  a.stepDt = 0.01;
  a.steps = 3000;
  a.duration = 30.0;
  Vec3 tip = Vec3::Zero();
  for (int i = 0; i < a.steps; ++i) {
    if (i % 3 == 0 && i < 600) tip.x() += 0.05;
    for (auto& hand : a.motion) {
      MotionSample s;
      s.time = (i + 1) * a.stepDt;
      s.tracked = true;
      s.position = &hand == &a.motion[1] ? tip : Vec3::Zero();
      hand.push_back(s);
    }
  }
  return a;
}

TEST(FairGrading, SteppedInputHasSmoothnessAndIdleTimeNotApplicable) {
  const Attempt keys = keyboardAttempt();
  EXPECT_TRUE(steppedInput(keys));
  const AttemptMetrics m = computeMetrics(keys);
  for (const char* key : {"smoothness", "idle_time"}) {
    const auto it = std::find_if(m.values.begin(), m.values.end(),
                                 [&](const MetricValue& v) { return v.key == key; });
    ASSERT_NE(it, m.values.end());
    EXPECT_FALSE(it->applicable) << key;
    EXPECT_TRUE(std::isnan(it->value)) << key;
  }
  EXPECT_TRUE(m.values.front().applicable);  // time

  // a tracked hand moves a little every step: smoothness and idle time apply
  Attempt tracker = keys;
  for (std::size_t i = 0; i < tracker.motion[1].size(); ++i)
    tracker.motion[1][i].position.x() = 0.002 * static_cast<double>(i) +
                                        0.0005 * std::sin(static_cast<double>(i));
  EXPECT_FALSE(steppedInput(tracker));
  EXPECT_TRUE(computeMetrics(tracker).value("smoothness").has_value());
  for (const MetricValue& v : computeMetrics(tracker).values) EXPECT_TRUE(v.applicable) << v.key;
}

TEST(FairGrading, NotApplicableMetricsAreWeightedOutNotScoredZero) {
  Rubric rubric;
  rubric.id = "motion";
  rubric.passMark = 70;
  RubricMetric time;
  time.key = "time";
  time.weight = 1;
  time.target = 60;
  time.tolerance = 30;
  time.limit = 90;
  time.bad = BadSide::Above;
  RubricMetric smoothness = time;
  smoothness.key = "smoothness";
  smoothness.weight = 2;
  smoothness.target = -6;
  smoothness.tolerance = 4;
  smoothness.limit = 14;
  smoothness.bad = BadSide::Below;
  RubricMetric idle = time;
  idle.key = "idle_time";
  idle.weight = 2;
  idle.target = 0;
  idle.tolerance = 5;
  idle.limit = 20;
  rubric.metrics = {time, smoothness, idle};

  const AttemptScore s = scoreAttempt(keyboardAttempt(), rubric);
  EXPECT_DOUBLE_EQ(s.score, 100.0);  // only time counts, and it is on target
  EXPECT_TRUE(s.passed);
  ASSERT_EQ(s.metrics.size(), 3u);
  EXPECT_FALSE(s.metrics[1].applicable);
  EXPECT_DOUBLE_EQ(s.metrics[1].weight, 0.0);
  EXPECT_EQ(s.metrics[1].feedback, "smoothness.not_applicable");
  EXPECT_EQ(s.metrics[2].feedback, "idle_time.not_applicable");

  // a metric the attempt merely lacks still scores 0 over its weight
  std::vector<MetricValue> values{{"time", 30.0, "s"},
                                  {"smoothness", std::nan(""), "1"},
                                  {"idle_time", 1.0, "s"}};
  const AttemptScore missing = scoreMetrics(values, rubric);
  EXPECT_DOUBLE_EQ(missing.score, 60.0);
  EXPECT_EQ(missing.metrics[1].feedback, "smoothness.missing");
}

}  // namespace
