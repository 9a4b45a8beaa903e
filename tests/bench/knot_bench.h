#pragma once
// The suture benchmark's knot rows (knot_bench.cpp): recognition per step and a suture step
// with a double throw drawn until the thread is taut, each beside its goal and with how often
// the knot was read right.

#include "bench_report.h"

namespace microsim::bench {

/// Appends the knot rows to `report`, naming each case to `progress` as it starts.
void appendKnotRows(BenchReport& report, const BenchOptions& options, BenchProgress& progress);

}  // namespace microsim::bench
