#pragma once
// Every attempt a viewer may see, as CSV (csv.h), one row each after a header row:
//   attempt, trainee, group, lesson, mode, status, started, finished, score, passed,
//   rubric, rubric_version
// Status is the stored word (in_progress, finished, interrupted, abandoned), times are
// ISO-8601 UTC, score and passed are empty unless the attempt was scored.

#include "microsim/assessment/storage/history_database.h"

#include <QIODevice>

namespace microsim::assessment {

HistoryStatus exportAttemptsCsv(HistoryDatabase& database, const Viewer& viewer, QIODevice& out);

}  // namespace microsim::assessment
