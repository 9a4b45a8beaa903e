#pragma once
// The suture benchmark (issue 5), registered in bench_registry.cpp.

#include "bench_report.h"

#include <string>

namespace microsim::bench {

BenchReport runSuture(const BenchOptions& options);  ///< suture_bench.cpp

/// The benchmark's workloads (see suture_bench.cpp's header comment).
enum class SutureBenchCase { OneGrip, TwoGrips, Sliding, Contacts };

/// What one run of one case measured.
struct SutureBenchMeasure {
  double microsPerStep = 0.0;  ///< CPU µs of the stepping thread per 10 ms step, mean over the frames
  double maxStretch = 0.0;     ///< max |relative link stretch| over every frame
  int breaks = 0;              ///< break events over the run
};

/// One case with solver `solver` ("ftl", "direct") and `links` links for `frames` frames.
SutureBenchMeasure measureSutureCase(const std::string& solver, SutureBenchCase c, int links,
                                     int frames);

}  // namespace microsim::bench
