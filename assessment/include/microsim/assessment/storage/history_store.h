#pragma once
// What every per-table store shares: the open HistoryDatabase it talks through (which must
// outlive it and stay on its thread) and the outcome of its last call.

#include "microsim/assessment/storage/history_database.h"

namespace microsim::assessment {

class HistoryStore {
 public:
  /// The outcome of the last call on this store.
  HistoryStatus lastError() const { return last_; }

 protected:
  explicit HistoryStore(HistoryDatabase& database) : db_(database) {}

  bool fail(HistoryError error, const QString& driverMessage = {}) {
    last_ = {error, driverMessage};
    return false;
  }
  bool succeed() {
    last_ = {};
    return true;
  }
  /// Fails with NotOpen when the database is closed.
  bool requireOpen() { return db_.isOpen() || fail(HistoryError::NotOpen); }

  HistoryDatabase& db_;

 private:
  HistoryStatus last_;
};

}  // namespace microsim::assessment
