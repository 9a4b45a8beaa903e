#pragma once
// Attempts put into a test's history the way the app stores them: scored through the scoring
// API against a shipped lesson's rubric, then begun and finished through the stores.
#include "lesson/lesson.h"

#include "microsim/assessment/scoring/metrics.h"
#include "microsim/assessment/scoring/score.h"
#include "microsim/assessment/storage/attempt_store.h"
#include "microsim/assessment/storage/score_store.h"

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <variant>
#include <vector>

namespace microsim::testing {

/// The rubric the shipped lesson `lessonId` names.
inline assessment::Rubric shippedLessonRubric(const QString& lessonId) {
  for (const lesson::Lesson& l : lesson::loadLessons(lesson::lessonsDirectory())) {
    if (l.id != lessonId) continue;
    auto loaded = assessment::loadRubric(l.rubricPath.toStdString());
    if (auto* rubric = std::get_if<assessment::Rubric>(&loaded)) return *rubric;
  }
  ADD_FAILURE() << "no shipped rubric for " << lessonId.toStdString();
  return {};
}

/// The score `rubric` gives an attempt whose metrics are at their targets (full points),
/// except the keys in `measured`, which take the value given.
inline assessment::AttemptScore scoreOnRubric(const assessment::Rubric& rubric,
                                              const std::map<std::string, double>& measured = {}) {
  std::vector<assessment::MetricValue> values;
  for (const assessment::RubricMetric& m : rubric.metrics) {
    const auto it = measured.find(m.key);
    values.push_back({m.key, it != measured.end() ? it->second : m.target, std::string(assessment::findMetric(m.key)->unit)});
  }
  return assessment::scoreMetrics(values, rubric);
}

/// The score of an attempt with every metric far on its bad side: no points, not passed.
inline assessment::AttemptScore failingScoreOnRubric(const assessment::Rubric& rubric) {
  std::map<std::string, double> measured;
  for (const assessment::RubricMetric& m : rubric.metrics) {
    const double far = 10 * (m.tolerance + m.limit + 1);
    measured[m.key] = m.bad == assessment::BadSide::Below ? m.target - far : m.target + far;
  }
  return scoreOnRubric(rubric, measured);
}

/// Begins and finishes an attempt of `trainee` with `score`; its id (0 on failure).
inline qint64 storeFinishedAttempt(assessment::HistoryDatabase& history, qint64 trainee, const QString& lesson,
                                   assessment::AttemptMode mode, const assessment::AttemptScore& score) {
  const std::optional<qint64> id = assessment::AttemptStore(history).begin(trainee, lesson, mode);
  EXPECT_TRUE(id);
  if (!id) return 0;
  assessment::ScoreStore scores(history);
  EXPECT_TRUE(scores.finish(*id, score, {})) << scores.lastError().driverMessage.toStdString();
  return *id;
}

}  // namespace microsim::testing
