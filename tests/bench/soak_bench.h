#pragma once
#include "bench_report.h"

namespace microsim::bench {

/// `bench soak`: a 30-minute simulated session (3 minutes with --quick) of the default
/// scene at 100 Hz, the shipped stitch recording looped; resident memory and step-time
/// percentiles sampled along it.
BenchReport runSoak(const BenchOptions& options);

}  // namespace microsim::bench
