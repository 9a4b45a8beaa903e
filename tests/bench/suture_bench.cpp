// suture: step time and maximum link stretch against link count (50 to 2000), for the paper's
// follow-the-leader ("ftl", the peer) and the direct tridiagonal solver ("direct"), in four
// cases: one grip moving the thread; two grips moving within the thread's slack; two grips
// with a pierce between them that the thread slides through; and two grips with contacts
// (draped over a cylinder surface, around a jaw capsule, self-contact on). The thread is
// 0.1 mm per link (so 2000 links = 200 mm), no needle; each frame is one 10 ms step with the
// default substeps. Times are wall-clock on one core, per frame, mean over the run.
#include "suture_bench.h"

#include "microsim/sim/suture/suture_solver.h"

#include <chrono>
#include <cmath>
#include <numbers>
#include <string>

namespace microsim::bench {

using namespace microsim::sim::suture;

namespace {

enum class Case { OneGrip, TwoGrips, Sliding, Contacts };

const char* caseName(Case c) {
  switch (c) {
    case Case::OneGrip: return "one grip";
    case Case::TwoGrips: return "two grips";
    case Case::Sliding: return "two grips + sliding pierce";
    case Case::Contacts: return "two grips + contacts";
  }
  return "";
}

// a triangle cylinder about the y axis under the thread's middle (radius 1 mm, normals out)
ContactSurface supportCylinder(double halfLength) {
  const int segments = 32;
  Points x(3, 2 * segments);
  std::vector<std::array<int, 3>> tris;
  for (int j = 0; j < segments; ++j) {
    const double a = 2.0 * std::numbers::pi * j / segments;
    x.col(j) = Vec3(std::cos(a), -halfLength, std::sin(a) - 1.02);
    x.col(segments + j) = Vec3(std::cos(a), halfLength, std::sin(a) - 1.02);
  }
  for (int j = 0; j < segments; ++j) {
    const int k = (j + 1) % segments;
    tris.push_back({j, segments + k, k});
    tris.push_back({j, segments + j, segments + k});
  }
  return ContactSurface(std::move(tris), x);
}

struct Measure {
  double microsPerStep = 0.0;
  double maxStretch = 0.0;
};

Measure run(const std::string& solverName, Case c, int links, int frames) {
  SutureDef def;
  def.links = links;
  def.needleLinks = 0;
  def.length = 0.1 * links;
  const SutureModel model(def);
  const double length = def.length;
  // the thread along x, centred on the origin, slightly sagging (not degenerate)
  SutureState state = SutureState::laidOut(model);
  for (int i = 0; i <= links; ++i) {
    const double t = static_cast<double>(i) / links;
    state.x.col(i) = Vec3((t - 0.5) * 0.9 * length, 0.0, -0.05 * length * std::sin(std::numbers::pi * t));
  }
  auto solver = makeSutureSolver(solverName);
  // settle the laid-out chain onto exact lengths first (not timed)
  const Grip settle[2] = {{0, Vec3(state.x.col(0))}, {links, Vec3(state.x.col(links))}};
  SutureStepParams params;
  params.projectionIterations = 200;
  makeSutureSolver("direct")->step(model, state, settle, {}, params);
  state.xPrev = state.x;
  if (c == Case::Sliding) {
    Pierce p;
    p.face = 0;
    p.node = links / 2;
    p.point = state.x.col(links / 2);
    state.pierces.push_back(p);
  }
  const ContactSurface surface = supportCylinder(2.0);
  SutureWorld world;
  if (c == Case::Contacts) {
    world.surface = &surface;
    world.capsules.push_back({Vec3(-0.2 * length, -1, 0.05), Vec3(-0.2 * length, 1, 0.05), 0.1});
  }
  const SutureStepParams stepParams;

  const Vec3 a0 = state.x.col(0);
  const Vec3 b0 = state.x.col(links);
  Measure m;
  double seconds = 0.0;
  for (int k = 1; k <= frames; ++k) {
    const double phase = 2.0 * std::numbers::pi * k / 100.0;
    const double hand = 0.02 * length;  // hand motion amplitude, mm
    Grip grips[2] = {{0, a0 + hand * Vec3(std::sin(phase), std::cos(phase) - 1.0, 0.3 * std::sin(2 * phase))},
                     {links, b0 + hand * Vec3(-std::sin(0.7 * phase), std::sin(phase), std::cos(phase) - 1.0)}};
    if (c == Case::Sliding) grips[1].position = b0 + Vec3(0.05 * length * std::sin(phase), 0, 0.05 * length);
    const std::span<const Grip> held(grips, c == Case::OneGrip ? 1 : 2);
    const auto start = std::chrono::steady_clock::now();
    const SutureStepReport r = solver->step(model, state, held, world, stepParams);
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    m.maxStretch = std::max(m.maxStretch, r.maxStretch);
  }
  m.microsPerStep = 1e6 * seconds / frames;
  return m;
}

}  // namespace

BenchReport runSuture(const BenchOptions& options) {
  BenchReport report;
  std::vector<int> sizes = {50, 100, 200, 500, 1000, 2000};
  if (options.quick) sizes = {50, 200};
  const int frames = options.quick ? 20 : 200;
  const Case cases[] = {Case::OneGrip, Case::TwoGrips, Case::Sliding, Case::Contacts};

  BenchPlot timePlot{"suture step time (two grips + contacts)", "links", "µs per step", true, true, {}};
  BenchPlot stretchPlot{"suture max stretch (two grips)", "links", "max |stretch|", true, true, {}};
  BenchCurve tFtl{"ftl (paper)", {}, {}}, tDirect{"direct", {}, {}};
  BenchCurve sFtl{"ftl (paper)", {}, {}}, sDirect{"direct", {}, {}};

  for (const Case c : cases) {
    for (int n : sizes) {
      const Measure ftl = run("ftl", c, n, frames);
      const Measure direct = run("direct", c, n, frames);
      const std::string name = std::string(caseName(c)) + ", " + std::to_string(n) + " links";
      const auto row = [&](const std::string& solver, const char* metric, double value,
                           const char* unit, std::optional<double> peer) {
        BenchRow r{"suture", name + " [" + solver + "]", metric, value, unit, std::nullopt, peer,
                   std::nullopt};
        if (peer && *peer > 0.0) r.ratio = value / *peer;
        report.rows.push_back(r);
      };
      row("ftl", "step time", ftl.microsPerStep, "us", std::nullopt);
      row("ftl", "max stretch", ftl.maxStretch, "relative", std::nullopt);
      row("direct", "step time", direct.microsPerStep, "us", ftl.microsPerStep);
      row("direct", "max stretch", direct.maxStretch, "relative", ftl.maxStretch);
      if (c == Case::Contacts) {
        tFtl.x.push_back(n);
        tFtl.y.push_back(ftl.microsPerStep);
        tDirect.x.push_back(n);
        tDirect.y.push_back(direct.microsPerStep);
      }
      if (c == Case::TwoGrips) {
        sFtl.x.push_back(n);
        sFtl.y.push_back(std::max(ftl.maxStretch, 1e-16));
        sDirect.x.push_back(n);
        sDirect.y.push_back(std::max(direct.maxStretch, 1e-16));
      }
    }
  }
  timePlot.curves = {tFtl, tDirect};
  stretchPlot.curves = {sFtl, sDirect};
  report.plots = {timePlot, stretchPlot};
  return report;
}

}  // namespace microsim::bench
