#pragma once
// Progress of long work as lines on stderr, at most one line per `gap`. The working thread
// says which step it has started; a step that starts less than `gap` after the last line
// waits, and a watcher thread prints it once the gap is over if it is still the latest step.
// So the last line always names the step running (at most `gap` late), every step that runs
// longer than `gap` gets its line, and fast work does not flood the terminal. The lines go to
// the stream given (the command's stderr), never to stdout or an output file.

#include <QString>
#include <QTextStream>

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <thread>

namespace microsim::cli {

class ProgressLines {
 public:
  using Clock = std::chrono::steady_clock;

  explicit ProgressLines(QTextStream& err, Clock::duration gap = std::chrono::seconds(1));
  /// Stops the watcher; a step still waiting for its line is dropped (the work is over).
  ~ProgressLines();
  ProgressLines(const ProgressLines&) = delete;
  ProgressLines& operator=(const ProgressLines&) = delete;

  /// The work has started the step `line` (one line, without its newline).
  void step(const QString& line);

 private:
  void watch();
  void printPendingLocked();

  QTextStream& err_;
  const Clock::duration gap_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::optional<QString> pending_;  ///< the latest step, not printed yet
  std::optional<Clock::time_point> lastLine_;
  bool done_ = false;
  std::thread watcher_;  ///< last: starts once every other member is ready
};

}  // namespace microsim::cli
