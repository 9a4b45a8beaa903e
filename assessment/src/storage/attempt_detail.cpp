#include "microsim/assessment/storage/attempt_detail.h"

#include "microsim/assessment/storage/annotation_store.h"
#include "microsim/assessment/storage/attempt_store.h"
#include "microsim/assessment/storage/score_store.h"

#include <utility>

namespace microsim::assessment {

std::optional<AttemptDetail> readAttemptDetail(HistoryDatabase& database, const Viewer& viewer,
                                               qint64 attemptId, HistoryStatus* status) {
  const auto failed = [status](const HistoryStatus& why) {
    if (status) *status = why;
    return std::nullopt;
  };
  AttemptStore attempts(database);
  std::optional<AttemptSummary> summary = attempts.summary(viewer, attemptId);
  if (!summary) return failed(attempts.lastError());
  ScoreStore scores(database);
  std::optional<StoredScore> score = scores.load(viewer, attemptId);
  if (!score) return failed(scores.lastError());
  AnnotationStore notes(database);
  std::optional<QList<Annotation>> annotations = notes.list(viewer, attemptId);
  if (!annotations) return failed(notes.lastError());

  AttemptDetail d;
  d.summary = std::move(*summary);
  d.metrics = std::move(score->metrics);
  d.pierces = std::move(score->pierces);
  d.neverEvents = std::move(score->neverEvents);
  d.endProduct = std::move(score->endProduct);
  d.recording = std::move(score->recording);
  d.annotations = std::move(*annotations);
  if (status) *status = {};
  return d;
}

}  // namespace microsim::assessment
