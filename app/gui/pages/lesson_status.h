#pragma once
// A trainee's standing in one lesson, from their attempts (oldest first):
//   NotStarted  no attempt;
//   Practised   attempts, but no finished Test attempt at the pass mark;
//   Passed      a finished Test attempt at the pass mark;
//   Proficient  the pass mark on two consecutive finished Test attempts (assessment::proficient).
// Learn attempts count as practice only; interrupted and abandoned attempts count as practice.

#include "microsim/assessment/scoring/rubric.h"
#include "microsim/assessment/storage/history_types.h"

#include <QList>
#include <QString>

namespace microsim::gui {

enum class LessonStatus { NotStarted, Practised, Passed, Proficient };

LessonStatus lessonStatus(const QList<assessment::AttemptSummary>& attemptsOldestFirst,
                          const QString& lessonId, const assessment::Rubric& rubric);

}  // namespace microsim::gui
