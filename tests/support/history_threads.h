#pragma once
// Records the thread of every access to any history (HistoryDatabase::setAccessObserver)
// while an instance lives, so that a test can assert that work stayed off the GUI thread.
#include "microsim/assessment/storage/history_database.h"

#include <QCoreApplication>
#include <QThread>

#include <algorithm>
#include <mutex>
#include <vector>

namespace microsim::testing {

// the thread of every access to any history while it is installed
class HistoryThreads {
 public:
  HistoryThreads() {
    assessment::HistoryDatabase::setAccessObserver([this](const assessment::HistoryDatabase&) {
      const std::lock_guard lock(mutex_);
      threads_.push_back(QThread::currentThread());
    });
  }
  ~HistoryThreads() { assessment::HistoryDatabase::setAccessObserver({}); }
  HistoryThreads(const HistoryThreads&) = delete;
  HistoryThreads& operator=(const HistoryThreads&) = delete;

  int accesses() const {
    const std::lock_guard lock(mutex_);
    return static_cast<int>(threads_.size());
  }
  int onGuiThread() const {
    const std::lock_guard lock(mutex_);
    return static_cast<int>(std::count(threads_.begin(), threads_.end(), QCoreApplication::instance()->thread()));
  }

 private:
  mutable std::mutex mutex_;
  std::vector<QThread*> threads_;
};

}  // namespace microsim::testing
