// `bench scene`: per-frame step time, median and p99, split by stage (collision, tissue,
// suture, interactions, total), over one full stitch: the shipped recording
// resources/recordings/stitch.msrec on resources/scenes/anastomosis.json (two vessel ends,
// two forceps, needle and suture), and the same scripted stitch on the ~10k-node fine vessel
// pair (fine_anastomosis.json; left out by --quick). Deterministic stepping (iteration
// limits, no clock in the solve), one core; the fine pair also in real-time stepping (the
// tissue solve stops at the step's 8 ms budget). Stage times are thread-CPU time (the
// scene's clock), so that other load on the machine does not change them. Issue 6's
// targets: p99 ≤ 5 ms for the default scene, ≤ 10 ms for the fine one.
#include "scene_bench.h"

#include "bench_clock.h"

#include "microsim/sim/scene/recording.h"
#include "microsim/sim/scene/scene.h"
#include "microsim/sim/scene/stitch_script.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <variant>
#include <vector>

namespace microsim::bench {

namespace {

const std::string kSceneBenchRoot = MICROSIM_SOURCE_DIR;

void runCase(const std::string& name, const std::string& sceneFile, bool shipped, sim::StepMode mode,
             BenchProgress& progress, BenchReport& report) {
  progress.next(name);
  sim::SceneDefLoad load = sim::loadSceneDef(kSceneBenchRoot + "/resources/scenes/" + sceneFile);
  if (!std::holds_alternative<sim::SceneDef>(load)) return;
  sim::SceneDef def = std::get<sim::SceneDef>(std::move(load));
  sim::Recording rec;
  if (!shipped || !sim::readRecording(kSceneBenchRoot + "/resources/recordings/stitch.msrec", rec).ok())
    rec = sim::scriptedStitch(def);
  const int nodes = def.tissue.model.nodeCount();
  sim::Scene scene(std::move(def), mode, cpuSeconds);

  std::array<std::vector<double>, 5> t;
  for (const sim::InputFrame& f : rec.frames) {
    const sim::StepReport r = scene.step(f);
    t[0].push_back(r.times.collision);
    t[1].push_back(r.times.tissue);
    t[2].push_back(r.times.suture);
    t[3].push_back(r.times.interactions);
    t[4].push_back(r.times.total);
  }
  const char* stages[5] = {"collision", "tissue", "suture", "interactions", "total"};
  const std::string label = name + " (" + std::to_string(nodes) + " nodes, " +
                            std::to_string(rec.frames.size()) + " frames)";
  for (int s = 0; s < 5; ++s) {
    const auto& v = t[static_cast<std::size_t>(s)];
    report.rows.push_back({"scene", label, std::string(stages[s]) + " median", quantileMs(v, 0.5), "ms", {}, {}, {}});
    report.rows.push_back({"scene", label, std::string(stages[s]) + " p99", quantileMs(v, 0.99), "ms", {}, {}, {}});
  }
  report.rows.push_back({"scene", label, "pierce events", static_cast<double>(scene.pierces().size()), "events", {}, {}, {}});

  // the step time along the stitch
  BenchPlot plot;
  plot.title = "scene step time over one stitch: " + name;
  plot.xLabel = "frame";
  plot.yLabel = "ms";
  for (int s : {0, 1, 2, 4}) {
    BenchCurve c;
    c.label = stages[s];
    for (std::size_t k = 0; k < t[static_cast<std::size_t>(s)].size(); ++k) {
      c.x.push_back(static_cast<double>(k));
      c.y.push_back(1e3 * t[static_cast<std::size_t>(s)][k]);
    }
    plot.curves.push_back(std::move(c));
  }
  report.plots.push_back(std::move(plot));
}

}  // namespace

BenchReport runScene(const BenchOptions& options) {
  BenchReport report;
  BenchProgress progress(options.progress, options.quick ? 1 : 3);
  runCase("two vessel ends", "anastomosis.json", true, sim::StepMode::Deterministic, progress, report);
  if (options.quick) return report;
  runCase("fine vessel ends", "fine_anastomosis.json", false, sim::StepMode::Deterministic, progress, report);
  runCase("fine vessel ends, real time", "fine_anastomosis.json", false, sim::StepMode::RealTime, progress, report);
  return report;
}

}  // namespace microsim::bench
