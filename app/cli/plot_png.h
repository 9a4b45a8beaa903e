#pragma once
// Draws a benchmark's curves to a PNG with QPainter (linear or log axes, a legend),
// so `bench ... --plot FILE.png` needs no display and no plotting library.
#include "bench_report.h"

#include <QString>

namespace microsim::cli {

/// Writes `plots` stacked vertically into one PNG; false if nothing could be written.
bool writePlotPng(const std::vector<bench::BenchPlot>& plots, const QString& file);

}  // namespace microsim::cli
