// table1: iterations of qss within 1/30 s on the paper's lattice boxes, without and with
// the computation cutout (Brown et al. 2002, Table 1). Protocol: bottom face fixed, the
// middle node of the top face displaced up by one unit per cycle, qss run for 1/30 s per
// cycle; the figure is the mean over 5 cycles. The 1/30 s is CPU time of the solving
// thread, which on an idle core is the wall clock the paper used, and which other load on
// the machine does not shrink.
#include "bench_report.h"
#include "tissue_bench_util.h"
#include "tissue_benches.h"

#include "microsim/sim/mesh/lattice.h"

#include <string>

namespace microsim::bench {

using namespace microsim::sim;

namespace {

constexpr double kCycle = 1.0 / 30.0;
constexpr int kCycles = 5;
/// The cutout threshold: 0.1 % of the per-cycle displacement (mm).
constexpr double kCutout = 1e-3;

struct PaperRow {
  int n;
  double without;
  double with;
};
constexpr PaperRow kPaper[] = {{6, 24, 248}, {8, 9.5, 13}, {10, 4.6, 8}, {15, 1.2, 7}, {20, 0.4, 6}};

double meanIterations(const SpringModel& model, int n, double cutout) {
  SolverParams params;
  params.cutout = cutout;
  auto solver = makeSolver("qss", params);
  SpringState state = SpringState::atRest(model);
  const int top = latticeTopMiddle(n);
  int total = 0;
  for (int cycle = 1; cycle <= kCycles; ++cycle) {
    SpringControls controls;
    controls.add(top, model.restPositions().col(top) + Vec3(0, 0, cycle));
    SolveBudget budget;
    budget.maxSeconds = kCycle;
    budget.clock = BudgetClock::ThreadCpu;
    total += solver->solve(model, state, controls, budget).iterations;
  }
  return static_cast<double>(total) / kCycles;
}

}  // namespace

BenchReport runTable1(const BenchOptions& options) {
  BenchReport report;
  std::vector<int> sizes = {6, 8, 10, 15, 20, 30, 40};
  if (options.quick) sizes = {6, 8, 10};
  BenchPlot plot{"qss iterations per 1/30 s", "nodes", "iterations", true, true, {}};
  BenchCurve without{"without cutout", {}, {}}, with{"with cutout", {}, {}};
  BenchCurve paperWithout{"paper, without cutout", {}, {}}, paperWith{"paper, with cutout", {}, {}};
  BenchProgress progress(options.progress, static_cast<int>(sizes.size()));
  for (int n : sizes) {
    progress.next(std::to_string(n) + "^3");
    const SpringModel model = latticeBox(n, 10.0);
    std::optional<double> paper[2];
    for (const PaperRow& p : kPaper)
      if (p.n == n) {
        paper[0] = p.without;
        paper[1] = p.with;
      }
    for (int c = 0; c < 2; ++c) {
      const double iterations = meanIterations(model, n, c == 0 ? 0.0 : kCutout);
      BenchRow row;
      row.bench = "table1";
      row.caseName = std::to_string(n) + "^3 " + (c == 0 ? "without cutout" : "with cutout");
      row.metric = "iterations per 1/30 s";
      row.value = iterations;
      row.unit = "iterations";
      row.paper = paper[c];
      if (paper[c]) row.ratio = iterations / *paper[c];
      report.rows.push_back(row);
      BenchCurve& curve = c == 0 ? without : with;
      curve.x.push_back(model.nodeCount());
      curve.y.push_back(iterations);
      if (paper[c]) {
        BenchCurve& p = c == 0 ? paperWithout : paperWith;
        p.x.push_back(model.nodeCount());
        p.y.push_back(*paper[c]);
      }
    }
  }
  plot.curves = {without, with, paperWithout, paperWith};
  report.plots.push_back(plot);
  return report;
}

}  // namespace microsim::bench
