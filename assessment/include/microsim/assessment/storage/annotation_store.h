#pragma once
// Instructors' notes on attempts (table annotations). Only instructors write them; the
// trainee whose attempt it is reads them too.

#include "microsim/assessment/storage/history_store.h"

#include <optional>

namespace microsim::assessment {

class AnnotationStore : public HistoryStore {
 public:
  explicit AnnotationStore(HistoryDatabase& database) : HistoryStore(database) {}

  /// Instructors only. Returns the annotation's id.
  std::optional<qint64> add(const Viewer& viewer, qint64 attemptId, const QString& note);
  /// The notes on an attempt the viewer may see, oldest first.
  std::optional<QList<Annotation>> list(const Viewer& viewer, qint64 attemptId);
};

}  // namespace microsim::assessment
