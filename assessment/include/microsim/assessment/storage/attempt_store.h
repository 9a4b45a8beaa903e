#pragma once
// The attempts of a history (table attempts): one row per attempt, from its start.
//
//   in_progress --ScoreStore::finish--> finished      (scored; never changes again)
//               --abandon-------------> abandoned     (the trainee gave up on it)
//               --sweep at open-------> interrupted   (its session ended without either:
//                                                      a crash, a kill, a closed window)
//
// Lists and summaries take a Viewer: a trainee reads only their own attempts (another's is
// Forbidden, not silently empty), an instructor everyone's.

#include "microsim/assessment/storage/history_store.h"

#include <optional>

namespace microsim::assessment {

class AttemptStore : public HistoryStore {
 public:
  explicit AttemptStore(HistoryDatabase& database) : HistoryStore(database) {}

  /// A new attempt in progress, tagged with the database's session.
  std::optional<qint64> begin(qint64 traineeId, const QString& lesson, AttemptMode mode);
  /// Marks an attempt in progress Abandoned. NotInProgress when it is not in progress.
  bool abandon(qint64 attemptId);
  /// Oldest first. A trainee gets only their own (asking for another's gives Forbidden
  /// and an empty list); an instructor gets everyone's, or `traineeId`'s.
  QList<AttemptSummary> list(const Viewer& viewer, std::optional<qint64> traineeId = {});
  std::optional<AttemptSummary> summary(const Viewer& viewer, qint64 attemptId);
  /// Marks Interrupted every attempt in progress whose session has ended
  /// (HistoryDatabase::sessionEnded); returns how many. HistoryDatabase::open calls it.
  int interruptEndedSessions();
};

}  // namespace microsim::assessment
