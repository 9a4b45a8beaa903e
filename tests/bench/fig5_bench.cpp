// fig5: qss's error on the paper's boxes (Brown et al. 2002, Fig. 5).
//  (a) max and mean error vs box size: 5 cycles of +1 unit on the top middle node, k = 10
//      iterations per cycle, error after each cycle against that cycle's equilibrium;
//      the paper reports max ≈ 2 × mean and max at most ~10 % of the displacement.
//  (b) max error after one unit displacement vs k = 5, 10, 20, 50, 100, without and with
//      the cutout, on two boxes.
// Errors are node distances to the reference equilibrium in % of the control node's
// displacement from rest (c units after cycle c: the paper's "magnitude of the
// displacement of the control node"), over all nodes (fixed ones included, as in the
// paper's average).
#include "bench_report.h"
#include "tissue_bench_util.h"
#include "tissue_benches.h"

#include "microsim/sim/mesh/lattice.h"

#include <algorithm>
#include <string>

namespace microsim::bench {

using namespace microsim::sim;

namespace {

constexpr double kFig5Cutout = 1e-3;  ///< mm, as in table1

/// qss as the paper tuned it: the largest step that still converges (ω = 1.5, see
/// benchParams).
SolverParams qssParams() { return benchParams("qss"); }

SpringControls topAt(const SpringModel& model, int n, double z) {
  SpringControls c;
  const int top = latticeTopMiddle(n);
  c.add(top, model.restPositions().col(top) + Vec3(0, 0, z));
  return c;
}

Errors errorAgainst(const Points& x, const Points& reference) {
  const Eigen::RowVectorXd d = (x - reference).colwise().norm();
  return {100.0 * d.maxCoeff(), 100.0 * d.mean()};
}

BenchRow fig5Row(const std::string& caseName, const std::string& metric, double value,
             std::optional<double> paper = {}) {
  BenchRow r;
  r.bench = "fig5";
  r.caseName = caseName;
  r.metric = metric;
  r.value = value;
  r.unit = "% of displacement";
  r.paper = paper;
  if (paper) r.ratio = value / *paper;
  return r;
}

}  // namespace

BenchReport runFig5(const BenchOptions& options) {
  BenchReport report;

  // (a) error vs box size over 5 cycles
  std::vector<int> sizes = {3, 4, 6, 8, 10, 15, 20};
  if (options.quick) sizes = {3, 4, 6};
  BenchPlot sizePlot{"qss error after k = 10 iterations per cycle", "nodes", "error (% of displacement)",
                     true, false, {}};
  // five curves at most, so that every colour of the legend is its own
  BenchCurve worstMaxCurve{"max, worst of 5 cycles", {}, {}}, worstMeanCurve{"mean, worst of 5 cycles", {}, {}};
  BenchCurve lastMaxCurve{"max, cycle 5", {}, {}}, lastMeanCurve{"mean, cycle 5", {}, {}};
  BenchCurve paperCurve{"paper: max at most ~10 %", {}, {}};
  const std::vector<int> boxes = options.quick ? std::vector<int>{4, 6} : std::vector<int>{10, 20};
  BenchProgress progress(options.progress, static_cast<int>(sizes.size() + boxes.size()));
  for (int n : sizes) {
    const std::string name = std::to_string(n) + "^3, 5 cycles, k = 10";
    progress.next(name);
    const SpringModel model = latticeBox(n, 10.0);
    auto solver = makeSolver("qss", qssParams());
    SpringState state = SpringState::atRest(model);
    SpringState reference = state;
    double worstMax = 0.0, worstMean = 0.0;
    for (int cycle = 1; cycle <= 5; ++cycle) {
      const SpringControls controls = topAt(model, n, cycle);
      SolveBudget budget;
      budget.maxIterations = 10;
      solver->solve(model, state, controls, budget);
      reference = referenceEquilibrium(model, reference, controls);
      Errors e = errorAgainst(state.x, reference.x);
      e.maxPercent /= cycle;  // of the control node's displacement so far
      e.meanPercent /= cycle;
      worstMax = std::max(worstMax, e.maxPercent);
      worstMean = std::max(worstMean, e.meanPercent);
      if (cycle == 5) {
        lastMaxCurve.x.push_back(model.nodeCount());
        lastMaxCurve.y.push_back(e.maxPercent);
        lastMeanCurve.x.push_back(model.nodeCount());
        lastMeanCurve.y.push_back(e.meanPercent);
      }
    }
    worstMaxCurve.x.push_back(model.nodeCount());
    worstMaxCurve.y.push_back(worstMax);
    worstMeanCurve.x.push_back(model.nodeCount());
    worstMeanCurve.y.push_back(worstMean);
    paperCurve.x.push_back(model.nodeCount());
    paperCurve.y.push_back(10.0);
    report.rows.push_back(fig5Row(name, "max error (worst cycle; paper: at most ~10 %)", worstMax, 10.0));
    report.rows.push_back(fig5Row(name, "mean error (worst cycle)", worstMean));
  }
  sizePlot.curves = {worstMaxCurve, worstMeanCurve, lastMaxCurve, lastMeanCurve, paperCurve};
  report.plots.push_back(sizePlot);

  // (b) max error vs k, without and with cutout
  BenchPlot kPlot{"qss max error after one unit displacement", "iterations k", "max error (% of displacement)",
                  true, true, {}};
  for (int n : boxes) {
    progress.next(std::to_string(n) + "^3, k = 5 to 100, without and with cutout");
    const SpringModel model = latticeBox(n, 10.0);
    const SpringControls controls = topAt(model, n, 1.0);
    const SpringState reference = referenceEquilibrium(model, SpringState::atRest(model), controls);
    for (int c = 0; c < 2; ++c) {
      BenchCurve curve{std::to_string(n) + "^3 " + (c == 0 ? "without cutout" : "with cutout"), {}, {}};
      for (int k : {5, 10, 20, 50, 100}) {
        SolverParams params = qssParams();
        params.cutout = c == 0 ? 0.0 : kFig5Cutout;
        SpringState state = SpringState::atRest(model);
        SolveBudget budget;
        budget.maxIterations = k;
        makeSolver("qss", params)->solve(model, state, controls, budget);
        const double e = errorAgainst(state.x, reference.x).maxPercent;
        report.rows.push_back(fig5Row(curve.label + ", k = " + std::to_string(k), "max error", e));
        curve.x.push_back(k);
        curve.y.push_back(e);
      }
      kPlot.curves.push_back(curve);
    }
  }
  report.plots.push_back(kPlot);
  return report;
}

}  // namespace microsim::bench
