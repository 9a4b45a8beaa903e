#pragma once
// What every benchmark returns, and the one JSON shape all of them write:
// an array of rows {"bench", "case", "metric", "value", "unit"} plus, where known,
// "paper" (the paper's figure for the same row), "peer" (the same measurement through
// a peer library or our faithful re-implementation) and "ratio" (value / peer, or
// value / paper when no peer ran). Curves travel beside the rows for plotting.

#include "bench_progress.h"

#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace microsim::bench {

struct BenchRow {
  std::string bench;   ///< e.g. "table1"
  std::string caseName;  ///< e.g. "20^3 cutout"
  std::string metric;  ///< e.g. "iterations per 1/30 s"
  double value = 0.0;
  std::string unit;
  std::optional<double> paper;
  std::optional<double> peer;
  std::optional<double> ratio;
};

/// One curve for a plot: y against x, drawn as a line with markers.
struct BenchCurve {
  std::string label;
  std::vector<double> x;
  std::vector<double> y;
};

struct BenchPlot {
  std::string title;
  std::string xLabel;
  std::string yLabel;
  bool logX = false;
  bool logY = false;
  std::vector<BenchCurve> curves;
};

struct BenchReport {
  std::vector<BenchRow> rows;
  std::vector<BenchPlot> plots;
};

struct BenchOptions {
  bool quick = false;  ///< smaller sizes, lower caps, fewer repetitions: under a minute (smoke tests)
  unsigned seed = 1;   ///< for the random workloads
  BenchListener progress;  ///< told as each case starts (bench_progress.h); may be empty
};

using BenchFunction = std::function<BenchReport(const BenchOptions&)>;

struct BenchEntry {
  std::string name;
  std::string summary;  ///< one line for --help; the CLI translates the table around it
  BenchFunction run;
};

/// Every benchmark, in the order `microsim-cli bench --list` shows them.
const std::vector<BenchEntry>& benchRegistry();
const BenchEntry* findBench(const std::string& name);

/// The rows as the JSON array described above.
std::string toJson(const std::vector<BenchRow>& rows);
/// The rows as an aligned plain-text table (bench, case, metric, ours, unit, paper, peer, ratio).
void printTable(std::ostream& out, const std::vector<BenchRow>& rows);

}  // namespace microsim::bench
