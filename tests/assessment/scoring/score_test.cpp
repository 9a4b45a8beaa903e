// Scoring a hand-made metric set with a rubric: points inside, across and past the
// tolerance band, feedback keys by side, NaN metrics, never-event caps, how the task was done
// counted only once some of it was, and proficiency.
#include "microsim/assessment/scoring/score.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using namespace microsim::assessment;

RubricMetric metric(const std::string& key, double weight, double target, double tol, double limit,
                    BadSide bad) {
  RubricMetric m;
  m.key = key;
  m.weight = weight;
  m.target = target;
  m.tolerance = tol;
  m.limit = limit;
  m.bad = bad;
  m.feedbackAbove = key + ".too_high";
  m.feedbackBelow = key + ".too_low";
  return m;
}

TEST(Score, PointsAreFullInsideTheToleranceAndFallLinearlyToTheLimit) {
  const RubricMetric angle = metric("entry_angle", 1, 0, 15, 45, BadSide::Above);
  EXPECT_DOUBLE_EQ(scoreMetric(angle, 10, "deg").points, 1.0);
  EXPECT_EQ(scoreMetric(angle, 10, "deg").feedback, "");
  EXPECT_DOUBLE_EQ(scoreMetric(angle, 30, "deg").points, 0.5);
  EXPECT_EQ(scoreMetric(angle, 30, "deg").feedback, "entry_angle.too_high");
  EXPECT_DOUBLE_EQ(scoreMetric(angle, 60, "deg").points, 0.0);
  EXPECT_DOUBLE_EQ(scoreMetric(angle, -60, "deg").points, 1.0);  // below is not bad

  const RubricMetric bite = metric("bite_walls", 1, 2.5, 0.5, 1.5, BadSide::Both);
  EXPECT_DOUBLE_EQ(scoreMetric(bite, 1.5, "1").points, 0.5);
  EXPECT_EQ(scoreMetric(bite, 1.5, "1").feedback, "bite_walls.too_low");
  EXPECT_DOUBLE_EQ(scoreMetric(bite, 3.5, "1").points, 0.5);
  EXPECT_EQ(scoreMetric(bite, 3.5, "1").feedback, "bite_walls.too_high");

  const MetricScore missing = scoreMetric(bite, std::numeric_limits<double>::quiet_NaN(), "1");
  EXPECT_DOUBLE_EQ(missing.points, 0.0);
  EXPECT_EQ(missing.feedback, "bite_walls.missing");
}

Rubric demoRubric() {
  Rubric r;
  r.id = "demo";
  r.version = 2;
  r.passMark = 70;
  r.metrics = {metric("entry_angle", 2, 0, 15, 45, BadSide::Above),
               metric("bite_walls", 1, 2.5, 0.5, 1.5, BadSide::Both),
               metric("time", 1, 60, 30, 90, BadSide::Above)};
  r.neverEvents = {{"back_wall_catches", 0, 0, "never.back_wall_catch"},
                   {"suture_breaks", 0, 40, "never.suture_break"}};
  return r;
}

TEST(Score, AWeightedMetricSetScoresItsKnownValue) {
  // entry 30° → 0.5 (weight 2), bite 2.5 → 1, time 100 s → 1 − 10/60: (1 + 1 + 5/6) / 4 · 100
  const std::vector<MetricValue> values{{"entry_angle", 30, "deg"}, {"bite_walls", 2.5, "1"},
                                        {"time", 100, "s"}, {"back_wall_catches", 0, "count"},
                                        {"suture_breaks", 0, "count"}};
  const AttemptScore s = scoreMetrics(values, demoRubric());
  EXPECT_NEAR(s.score, 100.0 * (1.0 + 1.0 + 5.0 / 6.0) / 4.0, 1e-9);
  EXPECT_TRUE(s.passed);
  EXPECT_EQ(s.rubricId, "demo");
  EXPECT_EQ(s.rubricVersion, 2);
  ASSERT_EQ(s.metrics.size(), 3u);
  EXPECT_EQ(s.metrics[0].key, "entry_angle");
  EXPECT_EQ(s.metrics[0].unit, "deg");
  EXPECT_DOUBLE_EQ(s.metrics[0].weight, 2.0);
  EXPECT_EQ(s.metrics[2].feedback, "time.too_high");
  EXPECT_TRUE(s.neverEvents.empty());
}

TEST(Score, NeverEventsCapTheScoreAndAMissingMetricScoresZero) {
  const std::vector<MetricValue> perfect{{"entry_angle", 0, "deg"}, {"bite_walls", 2.5, "1"},
                                         {"time", 10, "s"}, {"back_wall_catches", 0, "count"},
                                         {"suture_breaks", 1, "count"}};
  AttemptScore s = scoreMetrics(perfect, demoRubric());
  EXPECT_DOUBLE_EQ(s.score, 40.0);
  EXPECT_FALSE(s.passed);
  ASSERT_EQ(s.neverEvents.size(), 1u);
  EXPECT_EQ(s.neverEvents[0], "never.suture_break");

  std::vector<MetricValue> caught = perfect;
  caught[3].value = 1;
  EXPECT_DOUBLE_EQ(scoreMetrics(caught, demoRubric()).score, 0.0);

  const std::vector<MetricValue> partial{{"entry_angle", std::nan(""), "deg"}, {"bite_walls", 2.5, "1"}};
  s = scoreMetrics(partial, demoRubric());
  EXPECT_NEAR(s.score, 25.0, 1e-12);  // only the bite (weight 1 of 4) scores
  EXPECT_EQ(s.metrics[0].feedback, "entry_angle.missing");
  EXPECT_EQ(s.metrics[2].feedback, "time.missing");
}

// Time marked only_if_task_done: quick and idle is worth nothing until the task earns points
TEST(Score, HowTheTaskWasDoneCountsOnlyOnceSomeOfItWasDone) {
  Rubric r = demoRubric();
  r.metrics[2].onlyIfTaskDone = true;  // time
  // nothing done: the angle and the bite missing, the attempt quick
  const std::vector<MetricValue> idle{
      {"entry_angle", std::nan(""), "deg"}, {"bite_walls", std::nan(""), "1"}, {"time", 5, "s"}};
  AttemptScore s = scoreMetrics(idle, r);
  EXPECT_DOUBLE_EQ(s.score, 0.0);
  EXPECT_DOUBLE_EQ(s.metrics[2].points, 0.0);
  EXPECT_EQ(s.metrics[2].feedback, "task.not_done");
  EXPECT_DOUBLE_EQ(s.metrics[2].value, 5.0) << "the value is still reported";
  // without the mark the same attempt collected the time's points
  EXPECT_NEAR(scoreMetrics(idle, demoRubric()).score, 25.0, 1e-12);
  // some of the task done (a bite, no angle): time counts again
  const std::vector<MetricValue> bite{
      {"entry_angle", std::nan(""), "deg"}, {"bite_walls", 2.5, "1"}, {"time", 5, "s"}};
  s = scoreMetrics(bite, r);
  EXPECT_NEAR(s.score, 50.0, 1e-12);
  EXPECT_DOUBLE_EQ(s.metrics[2].points, 1.0);
  EXPECT_EQ(s.metrics[2].feedback, "");
  // a rubric of marked metrics only has no task to wait for
  Rubric onlyTime;
  onlyTime.metrics = {r.metrics[2]};
  EXPECT_DOUBLE_EQ(scoreMetrics({{"time", 5, "s"}}, onlyTime).score, 100.0);
}

TEST(Score, ProficiencyIsThePassMarkOnTwoConsecutiveTests) {
  const Rubric r = demoRubric();
  EXPECT_FALSE(proficient({}, r));
  EXPECT_FALSE(proficient({90}, r));
  EXPECT_FALSE(proficient({90, 60, 80, 40}, r));
  EXPECT_TRUE(proficient({50, 70, 71}, r));
  EXPECT_TRUE(proficient({80, 90, 10}, r));
}

}  // namespace
