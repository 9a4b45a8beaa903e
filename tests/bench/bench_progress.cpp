#include "bench_progress.h"

#include <utility>

namespace microsim::bench {

BenchProgress::BenchProgress(BenchListener listener, int count)
    : listener_(std::move(listener)), count_(count) {}

void BenchProgress::next(const std::string& caseName) {
  ++done_;
  if (listener_) listener_({caseName, done_, count_});
}

}  // namespace microsim::bench
