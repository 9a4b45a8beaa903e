#include "cli/progress_lines.h"

namespace microsim::cli {

ProgressLines::ProgressLines(QTextStream& err, Clock::duration gap)
    : err_(err), gap_(gap), watcher_([this] { watch(); }) {}

ProgressLines::~ProgressLines() {
  {
    const std::lock_guard lock(mutex_);
    done_ = true;
  }
  wake_.notify_one();
  watcher_.join();
}

void ProgressLines::step(const QString& line) {
  const std::lock_guard lock(mutex_);
  pending_ = line;
  if (!lastLine_ || Clock::now() - *lastLine_ >= gap_)
    printPendingLocked();
  else
    wake_.notify_one();
}

void ProgressLines::watch() {
  std::unique_lock lock(mutex_);
  while (!done_) {
    // nothing waiting: sleep until a step waits or the work is over
    if (!pending_) {
      wake_.wait(lock, [this] { return done_ || pending_.has_value(); });
      continue;
    }
    // a step waits for the gap after the last line: print it then, unless the work ends first
    const Clock::time_point due = *lastLine_ + gap_;
    if (!wake_.wait_until(lock, due, [this] { return done_; }) && pending_) printPendingLocked();
  }
}

void ProgressLines::printPendingLocked() {
  err_ << *pending_ << '\n';
  err_.flush();
  pending_.reset();
  lastLine_ = Clock::now();
}

}  // namespace microsim::cli
