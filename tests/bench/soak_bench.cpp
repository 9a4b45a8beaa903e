// `bench soak`: one long simulated training session, to show that nothing grows or drifts.
// A session is attempts back to back, as a resident retrying a lesson: each attempt opens
// the default scene (resources/scenes/anastomosis.json) afresh, as the app does, and replays
// the shipped stitch recording (resources/recordings/stitch.msrec, four pierces) at the
// scene's 100 Hz, for 30 simulated minutes (180,000 steps; 3 minutes with --quick). Every
// simulated minute the process's resident set (/proc/self/statm) and that minute's step-time
// percentiles are sampled. What must hold: resident memory at the end equals the first
// sample's (flat, within allocator noise), the p99 of the last minute matches the first's,
// no state goes non-finite, and every complete attempt ends in the same state hash and the
// same pierce count as the first (deterministic replays over a whole session).
#include "soak_bench.h"

#include "bench_clock.h"

#include "microsim/sim/scene/recording.h"
#include "microsim/sim/scene/scene.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <memory>
#include <string>
#include <unistd.h>
#include <variant>
#include <vector>

namespace microsim::bench {

namespace {

const std::string kSoakBenchRoot = MICROSIM_SOURCE_DIR;

double residentMiB() {
  std::ifstream statm("/proc/self/statm");
  long pagesTotal = 0;
  long pagesResident = 0;
  statm >> pagesTotal >> pagesResident;
  return static_cast<double>(pagesResident) * static_cast<double>(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

bool finiteState(const sim::Scene& scene) {
  if (!scene.tissueState().x.allFinite() || !scene.tissueState().v.allFinite()) return false;
  const auto* suture = scene.sutureState();
  return suture == nullptr || suture->x.allFinite();
}

}  // namespace

BenchReport runSoak(const BenchOptions& options) {
  BenchReport report;
  sim::SceneDefLoad load = sim::loadSceneDef(kSoakBenchRoot + "/resources/scenes/anastomosis.json");
  sim::Recording rec;
  if (!std::holds_alternative<sim::SceneDef>(load) ||
      !sim::readRecording(kSoakBenchRoot + "/resources/recordings/stitch.msrec", rec).ok() || rec.frames.empty()) {
    report.rows.push_back({"soak", "setup", "scene or recording unreadable", 1.0, "error", {}, {}, {}});
    return report;
  }
  const sim::SceneDef def = std::get<sim::SceneDef>(std::move(load));
  auto scene = std::make_unique<sim::Scene>(def, sim::StepMode::Deterministic, cpuSeconds);

  const double minutes = options.quick ? 3.0 : 30.0;
  const int stepsPerMinute = static_cast<int>(std::lround(60.0 / scene->dt()));
  const int totalSteps = static_cast<int>(minutes) * stepsPerMinute;

  BenchPlot memory{"soak: resident memory over the session", "simulated minute", "MiB", false, false, {}};
  BenchPlot p99{"soak: step time per simulated minute", "simulated minute", "ms", false, false, {}};
  BenchCurve rss{"resident set", {}, {}};
  BenchCurve p50Curve{"median", {}, {}};
  BenchCurve p99Curve{"p99", {}, {}};

  std::vector<double> minute;
  std::vector<double> all;
  minute.reserve(static_cast<std::size_t>(stepsPerMinute));
  all.reserve(static_cast<std::size_t>(totalSteps));
  int nonFinite = 0;
  int rejected = 0;
  int attempts = 0;
  int attemptsDiffering = 0;
  std::size_t pierces = 0;
  std::uint64_t firstHash = 0;
  std::size_t firstPierces = 0;
  double firstRss = 0.0;
  double peakRss = 0.0;
  double firstP99 = 0.0;
  double lastP99 = 0.0;
  const std::size_t n = rec.frames.size();
  BenchProgress progress(options.progress, static_cast<int>(minutes));
  for (int k = 0; k < totalSteps; ++k) {
    if (k % stepsPerMinute == 0) progress.next("simulated minute " + std::to_string(k / stepsPerMinute + 1));
    const std::size_t i = static_cast<std::size_t>(k) % n;
    if (i == 0 && k > 0) {
      // an attempt is over: it must end where the first one did, then the next one starts
      ++attempts;
      pierces += scene->pierces().size();
      if (attempts == 1) {
        firstHash = scene->hash();
        firstPierces = scene->pierces().size();
      } else if (scene->hash() != firstHash || scene->pierces().size() != firstPierces) {
        ++attemptsDiffering;
      }
      scene = std::make_unique<sim::Scene>(def, sim::StepMode::Deterministic, cpuSeconds);
    }
    const sim::StepReport r = scene->step(rec.frames[i]);
    if (r.inputRejected) ++rejected;
    minute.push_back(r.times.total);
    all.push_back(r.times.total);
    if ((k + 1) % stepsPerMinute == 0) {
      // NOLINTNEXTLINE(bugprone-integer-division): whole simulated minutes
      const double m = static_cast<double>((k + 1) / stepsPerMinute);
      if (!finiteState(*scene)) ++nonFinite;
      const double mib = residentMiB();
      const double q99 = quantileMs(minute, 0.99);
      if (m == 1.0) {
        firstRss = mib;
        firstP99 = q99;
      }
      lastP99 = q99;
      peakRss = std::max(peakRss, mib);
      rss.x.push_back(m);
      rss.y.push_back(mib);
      p50Curve.x.push_back(m);
      p50Curve.y.push_back(quantileMs(minute, 0.5));
      p99Curve.x.push_back(m);
      p99Curve.y.push_back(q99);
      minute.clear();
    }
  }

  const std::string label = std::to_string(static_cast<int>(minutes)) + " simulated min, " +
                            std::to_string(totalSteps) + " steps";
  const double lastRss = rss.y.empty() ? 0.0 : rss.y.back();
  report.rows.push_back({"soak", label, "resident memory after 1 min", firstRss, "MiB", {}, {}, {}});
  report.rows.push_back({"soak", label, "resident memory at the end", lastRss, "MiB", {}, {}, {}});
  report.rows.push_back({"soak", label, "resident memory growth", lastRss - firstRss, "MiB", {}, {}, {}});
  report.rows.push_back({"soak", label, "resident memory peak", peakRss, "MiB", {}, {}, {}});
  report.rows.push_back({"soak", label, "step median", quantileMs(all, 0.5), "ms", {}, {}, {}});
  report.rows.push_back({"soak", label, "step p99", quantileMs(all, 0.99), "ms", {}, {}, {}});
  report.rows.push_back({"soak", label, "step max", quantileMs(all, 1.0), "ms", {}, {}, {}});
  report.rows.push_back({"soak", label, "p99 of the first minute", firstP99, "ms", {}, {}, {}});
  report.rows.push_back({"soak", label, "p99 of the last minute", lastP99, "ms", {}, {}, {}});
  report.rows.push_back({"soak", label, "minutes ending in a non-finite state", static_cast<double>(nonFinite), "count", {}, {}, {}});
  report.rows.push_back({"soak", label, "frames rejected", static_cast<double>(rejected), "count", {}, {}, {}});
  report.rows.push_back({"soak", label, "complete attempts", static_cast<double>(attempts), "count", {}, {}, {}});
  report.rows.push_back({"soak", label, "pierce events in complete attempts", static_cast<double>(pierces), "count", {}, {}, {}});
  report.rows.push_back({"soak", label, "attempts ending unlike the first", static_cast<double>(attemptsDiffering), "count", {}, {}, {}});

  memory.curves.push_back(std::move(rss));
  p99.curves.push_back(std::move(p50Curve));
  p99.curves.push_back(std::move(p99Curve));
  report.plots.push_back(std::move(memory));
  report.plots.push_back(std::move(p99));
  return report;
}

}  // namespace microsim::bench
