#include "bench_clock.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>

namespace microsim::bench {

double nowSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double cpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double quantileMs(std::vector<double> seconds, double q) {
  if (seconds.empty()) return 0.0;
  std::sort(seconds.begin(), seconds.end());
  const std::size_t i = static_cast<std::size_t>(std::ceil(q * static_cast<double>(seconds.size()))) - 1;
  return 1e3 * seconds[std::min(i, seconds.size() - 1)];
}

}  // namespace microsim::bench
