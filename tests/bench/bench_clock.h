#pragma once
// The clocks and the percentile every benchmark reports with. Step and solve times are CPU
// time of the measuring thread: on a shared machine, wall clock would count other processes.

#include <vector>

namespace microsim::bench {

/// Seconds of wall clock since an arbitrary start.
double nowSeconds();
/// CPU seconds the calling thread has used.
double cpuSeconds();
/// The q-quantile (0 < q ≤ 1, nearest rank) of `seconds`, in milliseconds; 0 when empty.
double quantileMs(std::vector<double> seconds, double q);

}  // namespace microsim::bench
