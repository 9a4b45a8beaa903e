#include "bench_report.h"

namespace microsim::bench {

// Each benchmark lives in its own file and is listed here once.
const std::vector<BenchEntry>& benchRegistry() {
  static const std::vector<BenchEntry> entries = {};
  return entries;
}

}  // namespace microsim::bench
