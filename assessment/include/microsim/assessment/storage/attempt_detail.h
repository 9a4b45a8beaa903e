#pragma once
// Everything stored about one attempt, read through the stores with one viewer's rights:
// its summary (AttemptStore), stored score (ScoreStore) and notes (AnnotationStore).

#include "microsim/assessment/storage/history_database.h"

#include <optional>

namespace microsim::assessment {

/// nullopt with `status` saying why (Forbidden, NotFound, QueryFailed, ...).
std::optional<AttemptDetail> readAttemptDetail(HistoryDatabase& database, const Viewer& viewer,
                                               qint64 attemptId, HistoryStatus* status = nullptr);

}  // namespace microsim::assessment
