#pragma once
// What a finished attempt stored (tables scores, score_metrics, score_pierces,
// score_end_product, recordings): its score with the rubric's id and version, every metric,
// the values measured on each pierce, the end product's errors (end_product.h) and the
// recording it was graded from. Written once, with the
// attempt's change to Finished, in one transaction; SQL triggers refuse any later change.

#include "microsim/assessment/storage/history_store.h"

#include <QByteArray>
#include <QStringList>

#include <optional>
#include <vector>

namespace microsim::assessment {

struct AttemptScore;  // scoring/score.h

/// The stored rows of one finished attempt's score.
struct StoredScore {
  QList<StoredMetric> metrics;       ///< in the rubric's order
  QList<StoredPierceValue> pierces;  ///< by pierce, then key
  QStringList neverEvents;
  StoredEndProduct endProduct;
  QByteArray recording;              ///< the .msrec bytes; empty when none was stored
};

struct PierceMetrics;  // scoring/pierce_metrics.h

/// The passages a score's stored pierce values describe, in pierce order: what
/// pierceMetrics() measured when the attempt was scored (a key not stored, by an older
/// history, leaves its field at the default: −1 for an index, false for a flag).
std::vector<PierceMetrics> storedPassages(const QList<StoredPierceValue>& values);

class ScoreStore : public HistoryStore {
 public:
  explicit ScoreStore(HistoryDatabase& database) : HistoryStore(database) {}

  /// Stores score, metrics, pierce values, end-product errors and recording and marks the attempt
  /// Finished, in one transaction. NotInProgress when the attempt is not in progress.
  bool finish(qint64 attemptId, const AttemptScore& score, const QByteArray& recording);
  /// An attempt's stored score, empty lists for an attempt not finished; the viewer must
  /// be allowed to see the attempt.
  std::optional<StoredScore> load(const Viewer& viewer, qint64 attemptId);
  /// Only the end-product errors of an attempt (not judged for one not finished); the
  /// viewer must be allowed to see the attempt.
  std::optional<StoredEndProduct> endProduct(const Viewer& viewer, qint64 attemptId);
};

}  // namespace microsim::assessment
