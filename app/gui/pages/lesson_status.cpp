#include "gui/pages/lesson_status.h"

#include "microsim/assessment/scoring/score.h"

#include <vector>

namespace microsim::gui {

LessonStatus lessonStatus(const QList<assessment::AttemptSummary>& attemptsOldestFirst,
                          const QString& lessonId, const assessment::Rubric& rubric) {
  bool any = false;
  bool passed = false;
  std::vector<double> testScores;
  for (const assessment::AttemptSummary& a : attemptsOldestFirst) {
    if (a.lesson != lessonId) continue;
    any = true;
    if (a.mode != assessment::AttemptMode::Test || a.status != assessment::AttemptStatus::Finished || !a.score)
      continue;
    testScores.push_back(*a.score);
    if (*a.score >= rubric.passMark) passed = true;
  }
  if (!any) return LessonStatus::NotStarted;
  if (assessment::proficient(testScores, rubric)) return LessonStatus::Proficient;
  return passed ? LessonStatus::Passed : LessonStatus::Practised;
}

}  // namespace microsim::gui
