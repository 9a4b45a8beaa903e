// The leak test's verdict as metrics (`leaks`, `leak_gap`): a verdict only when the test was
// solved, and lesson 5's rubric (a whole anastomosis) caps a line that leaks, while the
// partial lines of lessons 3 and 4, which always leak, are not judged on it.
#include "microsim/assessment/scoring/metrics.h"
#include "microsim/assessment/scoring/rubric.h"
#include "microsim/assessment/scoring/score.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <variant>

namespace microsim::assessment {
namespace {

LeakFinding leakFindingOf(bool leaks, double gapMm, sim::LeakTestStatus status = sim::LeakTestStatus::Solved) {
  LeakFinding f;
  f.status = status;
  f.leaks = leaks;
  f.largestGapMm = gapMm;
  f.angleDeg = 90.0;
  f.limitMm = 0.05;
  f.pressureMmHg = 100.0;
  return f;
}

TEST(LeakMetrics, TheVerdictOfASolvedTestIsAMetricAndNoVerdictIsNaN) {
  Attempt held;
  held.leak = leakFindingOf(false, 0.03);
  Attempt open;
  open.leak = leakFindingOf(true, 0.11);
  Attempt unsolved;
  unsolved.leak = leakFindingOf(false, std::nan(""), sim::LeakTestStatus::NotConverged);
  Attempt untested;

  EXPECT_EQ(computeMetrics(held).value("leaks"), 0.0);
  EXPECT_EQ(computeMetrics(held).value("leak_gap"), 0.03);
  EXPECT_EQ(computeMetrics(open).value("leaks"), 1.0);
  EXPECT_EQ(computeMetrics(open).value("leak_gap"), 0.11);
  for (const Attempt* a : {&unsolved, &untested}) {
    EXPECT_TRUE(std::isnan(*computeMetrics(*a).value("leaks")));
    EXPECT_TRUE(std::isnan(*computeMetrics(*a).value("leak_gap")));
  }
  // a leak is not one of the lapse index's errors here: a partial line always leaks
  EXPECT_EQ(computeMetrics(open).value("lapse_index"), 0.0);
}

Rubric leakLessonRubric(const std::string& id) {
  const auto loaded = loadRubric(std::string(MICROSIM_SOURCE_DIR) + "/resources/rubrics/" + id + ".json");
  EXPECT_TRUE(std::holds_alternative<Rubric>(loaded)) << id;
  return std::holds_alternative<Rubric>(loaded) ? std::get<Rubric>(loaded) : Rubric{};
}

bool neverEventFired(const AttemptScore& s, const std::string& key) {
  return std::find(s.neverEvents.begin(), s.neverEvents.end(), key) != s.neverEvents.end();
}

TEST(LeakMetrics, OnlyTheFullAnastomosisIsCappedForALeak) {
  Attempt open;
  open.leak = leakFindingOf(true, 0.11);
  Attempt held;
  held.leak = leakFindingOf(false, 0.03);
  const AttemptScore full = scoreAttempt(open, leakLessonRubric("05_full_anastomosis"));
  EXPECT_TRUE(neverEventFired(full, "never.leak"));
  EXPECT_LE(full.score, 60.0);
  EXPECT_FALSE(neverEventFired(scoreAttempt(held, leakLessonRubric("05_full_anastomosis")), "never.leak"));
  for (const char* partial : {"03_single_stitch", "04_triangulation"})
    EXPECT_FALSE(neverEventFired(scoreAttempt(open, leakLessonRubric(partial)), "never.leak")) << partial;
}

}  // namespace
}  // namespace microsim::assessment
