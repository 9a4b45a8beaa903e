#include "gui/pages/lesson_status.h"

#include "microsim/assessment/scoring/score.h"

#include <vector>

namespace microsim::gui {

LessonStatus lessonStatus(const QList<assessment::AttemptSummary>& attemptsOldestFirst, qint64 traineeId,
                          const QString& lessonId, const assessment::Rubric* rubric) {
  bool any = false;
  bool passed = false;
  std::vector<double> testScores;
  for (const assessment::AttemptSummary& a : attemptsOldestFirst) {
    if (a.traineeId != traineeId || a.lesson != lessonId) continue;
    any = true;
    if (a.mode != assessment::AttemptMode::Test || a.status != assessment::AttemptStatus::Finished || !a.score)
      continue;
    testScores.push_back(*a.score);
    passed = passed || a.passed;
  }
  if (!any) return LessonStatus::NotStarted;
  if (rubric && assessment::proficient(testScores, *rubric)) return LessonStatus::Proficient;
  return passed ? LessonStatus::Passed : LessonStatus::Practised;
}

QString LessonStatusText::word(LessonStatus status) {
  switch (status) {
    case LessonStatus::NotStarted: return tr("not started");
    case LessonStatus::Practised: return tr("practised");
    case LessonStatus::Passed: return tr("passed");
    case LessonStatus::Proficient: return tr("proficient");
  }
  return {};
}

}  // namespace microsim::gui
