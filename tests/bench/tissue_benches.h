#pragma once
// The tissue benchmarks (issue 3), one file each, registered in bench_registry.cpp.

#include "bench_report.h"

namespace microsim::bench {

BenchReport runTable1(const BenchOptions& options);      ///< table1_bench.cpp
BenchReport runFig5(const BenchOptions& options);        ///< fig5_bench.cpp
BenchReport runSpeedError(const BenchOptions& options);  ///< speed_error_bench.cpp

}  // namespace microsim::bench
