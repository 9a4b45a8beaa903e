#pragma once
// The scene benchmark (issue 6), registered in bench_registry.cpp.

#include "bench_report.h"

namespace microsim::bench {

BenchReport runScene(const BenchOptions& options);  ///< scene_bench.cpp

}  // namespace microsim::bench
