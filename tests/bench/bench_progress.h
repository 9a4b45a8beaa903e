#pragma once
// How a benchmark tells its caller where it is. Before each of its cases a benchmark names
// the case and its place in the run ("20^3 stiffness 1000:1, warm", 7 of 14); the caller
// decides what to show (microsim-cli prints a line on stderr). A benchmark reports at its
// natural case boundaries only, outside every timed region, so a listener costs nothing the
// benchmark measures; with no listener it reports to nobody. Nothing here reaches the rows.

#include <functional>
#include <string>

namespace microsim::bench {

/// One case of a run, about to start.
struct BenchStep {
  std::string caseName;  ///< as the benchmark names it (its rows use the same words)
  int index = 0;         ///< 1-based place of the case in the run
  int count = 0;         ///< cases in the run
};

using BenchListener = std::function<void(const BenchStep&)>;

/// Numbers a run's cases and hands each to the listener as it starts.
class BenchProgress {
 public:
  /// `count` cases will follow; `listener` may be empty.
  BenchProgress(BenchListener listener, int count);

  /// The next case starts: reported as case k + 1 of `count`.
  void next(const std::string& caseName);

 private:
  BenchListener listener_;
  int count_ = 0;
  int done_ = 0;
};

}  // namespace microsim::bench
