#pragma once
// A person's standing in one lesson, from their attempts in it (oldest first):
//   NotStarted  no attempt;
//   Practised   attempts, but no finished Test attempt that passed;
//   Passed      a finished Test attempt that passed (its stored verdict: score ≥ the pass
//               mark of the rubric it was graded with);
//   Proficient  the pass mark on two consecutive finished Test attempts (assessment::proficient).
// Learn attempts count as practice only (they are guided); interrupted and abandoned attempts
// count as practice. The trainee's lesson list and the instructor's grid both ask this one
// function and show its word, so the two never disagree.

#include "microsim/assessment/scoring/rubric.h"
#include "microsim/assessment/storage/history_types.h"

#include <QCoreApplication>
#include <QList>
#include <QString>

namespace microsim::gui {

enum class LessonStatus { NotStarted, Practised, Passed, Proficient };

/// The status of `traineeId` in `lessonId`; `attemptsOldestFirst` may hold other people's and
/// other lessons' attempts (they are skipped). `rubric` null (the lesson is no longer shipped):
/// never Proficient, since proficiency needs the pass mark.
LessonStatus lessonStatus(const QList<assessment::AttemptSummary>& attemptsOldestFirst, qint64 traineeId,
                          const QString& lessonId, const assessment::Rubric* rubric);

class LessonStatusText {
  Q_DECLARE_TR_FUNCTIONS(microsim::gui::LessonStatusText)

 public:
  /// "not started", "practised", "passed", "proficient", in the UI language.
  static QString word(LessonStatus status);
};

}  // namespace microsim::gui
