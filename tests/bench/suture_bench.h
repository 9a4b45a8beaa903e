#pragma once
// The suture benchmark (issue 5), registered in bench_registry.cpp.

#include "bench_report.h"

namespace microsim::bench {

BenchReport runSuture(const BenchOptions& options);  ///< suture_bench.cpp

}  // namespace microsim::bench
