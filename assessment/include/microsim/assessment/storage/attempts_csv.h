#pragma once
// Every attempt a viewer may see, as CSV (csv.h), one row each after a header row:
//   attempt, trainee, group, lesson, mode, status, started, finished, score, passed,
//   rubric, rubric_version, end_product_errors, end_product_kinds
// Status is the stored word (in_progress, finished, interrupted, abandoned), times are
// ISO-8601 UTC, score and passed are empty unless the attempt was scored. The end product
// (scoring/end_product.h): the number of its errors and their kinds as stable keys
// (endProductErrorKey) separated by spaces, in the scorer's order, a kind once per error;
// both empty unless the attempt was judged so (scores stored before the history kept them
// were not).

#include "microsim/assessment/storage/history_database.h"

#include <QIODevice>

namespace microsim::assessment {

HistoryStatus exportAttemptsCsv(HistoryDatabase& database, const Viewer& viewer, QIODevice& out);

}  // namespace microsim::assessment
