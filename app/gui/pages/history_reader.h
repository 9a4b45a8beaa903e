#pragma once
// Reads the history off the GUI thread, for the pages that show it (the lesson list, "My
// progress").
//
// Each read runs on a thread of its own with a history connection of its own, opened, used
// and closed there (a QtSql connection belongs to the thread that opened it): the GUI thread
// makes no history call for it. What the read found comes back on this object's thread; when
// reads overlap (the page was shown again before the last one arrived) only the newest is
// delivered. The storage layer applies the viewer's rights as it does on any connection.

#include "microsim/assessment/storage/history_database.h"

#include <QObject>
#include <QString>

#include <functional>
#include <memory>
#include <mutex>
#include <vector>

class QThread;

namespace microsim::gui {

class HistoryReader : public QObject {
  Q_OBJECT

 public:
  /// `historyLocation`: what HistoryDatabase::open takes (an SQLite file or a PostgreSQL URL).
  explicit HistoryReader(QString historyLocation, QObject* parent = nullptr);
  /// Waits for the reads still running (they only read).
  ~HistoryReader() override;
  HistoryReader(const HistoryReader&) = delete;
  HistoryReader& operator=(const HistoryReader&) = delete;

  QString location() const { return location_; }

  /// Runs `query` on a reading thread with the history open there, or `failed` (with the
  /// reason) if it cannot be opened; then hands the result to `deliver` on this object's
  /// thread, unless a newer read has started since.
  template <typename Result>
  void read(std::function<Result(assessment::HistoryDatabase&)> query, std::function<Result(const QString&)> failed,
            std::function<void(const Result&)> deliver) {
    // the result crosses threads under a std::mutex, which ThreadSanitizer sees (Qt's own
    // futex-based hand-over it does not)
    struct Slot {
      std::mutex mutex;
      Result value;
    };
    auto slot = std::make_shared<Slot>();
    start(
        [query = std::move(query), failed = std::move(failed), slot](assessment::HistoryDatabase* history,
                                                                      const QString& why) {
          Result value = history ? query(*history) : failed(why);
          const std::lock_guard lock(slot->mutex);
          slot->value = std::move(value);
        },
        [deliver = std::move(deliver), slot] {
          Result value;
          {
            const std::lock_guard lock(slot->mutex);
            value = std::move(slot->value);
          }
          deliver(value);
        });
  }

 private:
  // `work` on a reading thread (the history, or null and why not), `done` back here if newest
  void start(std::function<void(assessment::HistoryDatabase*, const QString&)> work, std::function<void()> done);

  QString location_;
  quint64 latest_ = 0;
  std::vector<QThread*> running_;
};

}  // namespace microsim::gui
