// suture: step time and maximum link stretch against link count (50 to 2000), for the paper's
// follow-the-leader ("ftl", the peer) and the direct tridiagonal solver ("direct"), in four
// cases: one grip moving the thread; two grips moving within the thread's slack; two grips
// with a pierce between them that the thread slides through; and two grips with contacts
// (under gravity, draped over a cylinder surface, pressed by a jaw capsule that the first hand
// carries along its path, self-contact on). The jaw moves with the hand: a jaw held still
// while both grips rise 0.6 mm would hold the thread down on a path longer than the thread
// (≈ 1.6 % at 200 links), which no solver can meet without stretching.
//
// The thread is 0.1 mm per link (2000 links = 200 mm), no needle, laid at exact link lengths
// in a shallow sag whose span is its length less 0.5 mm, so every link count has the same
// slack. The hands move the same way for every link count, at hand speed: both grips follow
// one path of amplitude 2 mm per second (peak ≈ 15 mm/s, 0.15 mm per frame), the second grip
// also moves ±0.2 mm against the first (inside the slack: nothing breaks); in the sliding case
// the first grip and the pierce (at the middle node) hold still while the second grip pulls
// 0.4 mm out and back along the span each second (beyond its side's slack: the thread slides).
// Each frame is one 10 ms step with the default step parameters. Times are the stepping
// thread's CPU time on one core, per frame, mean over the run; the stretch is the largest
// over every frame. The knot rows that follow are knot_bench.cpp's.
#include "suture_bench.h"

#include "bench_clock.h"
#include "knot_bench.h"

#include "microsim/sim/suture/suture_solver.h"

#include <cmath>
#include <iterator>
#include <numbers>
#include <string>

namespace microsim::bench {

using namespace microsim::sim::suture;

namespace {

using Case = SutureBenchCase;

constexpr double kLink = 0.1;           // mm per link
constexpr double kSlack = 0.5;          // mm: length less span
constexpr double kHand = 2.0;           // mm: amplitude of the common hand path
constexpr double kRelative = 0.2;       // mm: second grip against the first
constexpr double kPull = 0.4;           // mm: the sliding case's pull
constexpr double kPeriod = 1.0;         // s: one cycle of every motion
constexpr double kFrame = 0.01;         // s

const char* caseName(Case c) {
  switch (c) {
    case Case::OneGrip: return "one grip";
    case Case::TwoGrips: return "two grips";
    case Case::Sliding: return "two grips + sliding pierce";
    case Case::Contacts: return "two grips + contacts";
  }
  return "";
}

// a triangle cylinder along y (radius 1 mm, y in [y0, y1], normals out) whose top is at `top`
ContactSurface supportCylinder(double top, double y0, double y1) {
  const int segments = 32;
  Points x(3, 2 * segments);
  std::vector<std::array<int, 3>> tris;
  for (int j = 0; j < segments; ++j) {
    const double a = 2.0 * std::numbers::pi * j / segments;
    x.col(j) = Vec3(std::cos(a), y0, std::sin(a) + top - 1.0);
    x.col(segments + j) = Vec3(std::cos(a), y1, std::sin(a) + top - 1.0);
  }
  for (int j = 0; j < segments; ++j) {
    const int k = (j + 1) % segments;
    tris.push_back({j, segments + k, k});
    tris.push_back({j, segments + j, segments + k});
  }
  return ContactSurface(std::move(tris), x);
}

// exact link lengths, tangent angle −θ0 cos(π s / L) in the xz plane, centred on x = 0; the
// span is L·J0(θ0), and θ0 = 2√(slack/L) gives a span of L − slack to first order
Points sagLayout(int links, double link, double slack) {
  const double length = links * link;
  const double theta0 = 2.0 * std::sqrt(slack / length);
  Points x(3, links + 1);
  x.col(0).setZero();
  for (int i = 0; i < links; ++i) {
    const double a = -theta0 * std::cos(std::numbers::pi * (i + 0.5) / links);
    x.col(i + 1) = x.col(i) + link * Vec3(std::cos(a), 0.0, std::sin(a));
  }
  x.colwise() -= Vec3(0.5 * x(0, links), 0.0, 0.0);
  return x;
}

// the common hand path at time t (s): amplitude kHand, one cycle per kPeriod
Vec3 handPath(double t) {
  const double phase = 2.0 * std::numbers::pi * t / kPeriod;
  return kHand * Vec3(std::sin(phase), std::cos(phase) - 1.0, 0.3 * std::sin(2.0 * phase));
}

}  // namespace

SutureBenchMeasure measureSutureCase(const std::string& solverName, Case c, int links, int frames) {
  SutureDef def;
  def.links = links;
  def.needleLinks = 0;
  def.length = kLink * links;
  SutureModel model(def);
  if (c == Case::Contacts) model.gravity = Vec3(0.0, 0.0, -9810.0);
  SutureState state = SutureState::laidOut(model);
  state.x = sagLayout(links, kLink, kSlack);
  state.xPrev = state.x;
  const int middle = links / 2;
  if (c == Case::Sliding) {
    Pierce p;
    p.face = 0;
    p.node = middle;
    p.point = state.x.col(middle);
    state.pierces.push_back(p);
  }
  // contacts: the cylinder just under the sag's lowest point, a jaw pressing a quarter along
  const ContactSurface surface = supportCylinder(state.x(2, middle) - 0.005, -6.0, 2.0);
  SutureWorld world;
  const Vec3 jawAt = state.x.col(links / 4) + Vec3(0.0, 0.0, 0.06);
  const auto jaw = [&](const Vec3& q) {
    return Capsule{Vec3(q.x(), -6.0, q.z()), Vec3(q.x(), 2.0, q.z()), 0.1};
  };
  if (c == Case::Contacts) {
    world.surface = &surface;
    world.capsules.push_back(jaw(jawAt));
  }
  auto solver = makeSutureSolver(solverName);
  const SutureStepParams stepParams;

  const Vec3 a0 = state.x.col(0);
  const Vec3 b0 = state.x.col(links);
  SutureBenchMeasure m;
  double seconds = 0.0;
  for (int k = 1; k <= frames; ++k) {
    const double t = k * kFrame;
    const double phase = 2.0 * std::numbers::pi * t / kPeriod;
    const Vec3 relative =
        kRelative * Vec3(std::sin(0.7 * phase), std::sin(phase), std::cos(phase) - 1.0);
    Grip grips[2] = {{0, a0 + handPath(t)}, {links, b0 + handPath(t) + relative}};
    if (c == Case::Sliding) {
      grips[0].position = a0;
      grips[1].position = b0 + Vec3(0.5 * kPull * (1.0 - std::cos(phase)), 0.0, 0.0);
    }
    if (c == Case::Contacts) world.capsules[0] = jaw(jawAt + handPath(t));
    const std::span<const Grip> held(grips, c == Case::OneGrip ? 1 : 2);
    const double start = cpuSeconds();
    const SutureStepReport r = solver->step(model, state, held, world, stepParams);
    seconds += cpuSeconds() - start;
    m.maxStretch = std::max(m.maxStretch, r.maxStretch);
    for (const SutureEvent& e : r.events) m.breaks += e.kind == SutureEventKind::Break ? 1 : 0;
  }
  m.microsPerStep = 1e6 * seconds / frames;
  return m;
}

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

  const int knotCases = options.quick ? 3 : 4;  // knot_bench.cpp: recognition per size, the tight knot
  BenchProgress progress(options.progress, static_cast<int>(std::size(cases) * sizes.size()) + knotCases);
  for (const Case c : cases) {
    for (int n : sizes) {
      const std::string name = std::string(caseName(c)) + ", " + std::to_string(n) + " links";
      progress.next(name);
      const SutureBenchMeasure ftl = measureSutureCase("ftl", c, n, frames);
      const SutureBenchMeasure direct = measureSutureCase("direct", c, n, frames);
      const auto row = [&](const std::string& solver, const char* metric, double value,
                           const char* unit, std::optional<double> peer) {
        std::string label = name;
        label += " [";
        label += solver;
        label += "]";
        BenchRow r{"suture", label, metric, value, unit, std::nullopt, peer,
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
  appendKnotRows(report, options, progress);
    timePlot.curves = {tFtl, tDirect};
  stretchPlot.curves = {sFtl, sDirect};
  report.plots = {timePlot, stretchPlot};
  return report;
}

}  // namespace microsim::bench
