// suture's knot rows (issue 19, item 8): what reading the knot costs a step, and a step of the
// suture solve with a double throw at a stitch pulled tight, each beside its goal and with its
// accuracy.
//
// Recognition. A surgeon's knot (a left double throw, then a right single: knot_geometry.h's
// analytic curves, scaled to a quarter) resampled into 60, 200 and 2000 equal links. Steady:
// the knot tracker (knot_tracker.h) reads the thread every step while the thread moves a
// little each step (a rigid drift of 0.02 mm a step and a turn of 0.1° a step, above the
// tracker's move tolerance, so every step is a reading): the mean over the steps read from the
// last clear picture's direction, and over all steps with the searches the tracker made when
// that picture turned unclear, and how many it made. Search: the
// full search over every direction (recogniseKnot without a hint), what the tracker pays when
// the picture it had stops being clear. Accuracy: the reading is a surgeon's knot of two
// throws on every step measured.
//
// Tight knot. A double throw round a stitch (knot_geometry.h's stitchTwist: two turns of the
// strands about each other above two pierces), resampled into 200 links, its two pierces held
// as the suture's pierces, both ends gripped and pulled outwards 0.01 mm a step until the
// thread is taut (a link stretched past the tracker's tightStrain, 0.2 %; at most 10 mm), then
// held there: the direct solver's step time over the held steps (the goal's "step with a knot
// pulled tight"), how far the ends were drawn, the largest link stretch over the whole pull and
// the tracker's KnotTightened events. The strands press on each other where they wind and the
// self-contact that ends each substep keeps them apart (suture_solver.cpp), so the double throw
// holds its two wraps while it is drawn down: the knot is read on each step, and a reading of
// one throw of two wraps is counted right.
#include "knot_bench.h"

#include "bench_clock.h"
#include "knot_geometry.h"

#include "microsim/sim/suture/knot_tracker.h"
#include "microsim/sim/suture/suture_solver.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace microsim::bench {

using namespace microsim::sim::suture;

namespace {

constexpr double kRecognitionGoalUs = 20.0;  // µs per step at 200 links
constexpr double kTightStepGoalUs = 200.0;   // µs per suture step, knot pulled tight, 200 links

bool isSurgeonsOfTwo(const KnotReading& r) {
  return r.type == KnotType::Surgeons && r.throws.size() == 2;
}

bool isDoubleThrow(const KnotReading& r) {
  return r.type == KnotType::SingleThrow && r.throws.size() == 1 && r.throws[0].wraps == 2;
}

Points surgeonsKnot(int links) {
  const knot_test::ThreadBuilder tied = knot_test::throwsInARow({{2, false}, {1, true}});
  return knot_test::evenlySpaced(tied.points(), 0.25, links);
}

struct RecognitionMeasure {
  double steadyUs = 0.0;  // mean over the steps read from the last picture
  double meanUs = 0.0;    // mean over every step, searches included
  double searchUs = 0.0;  // recogniseKnot without a hint
  int right = 0;
  int steps = 0;
  int searches = 0;  // of the tracker's steps, those that searched every direction
};

RecognitionMeasure measureRecognition(int links, int steps) {
  const Points knot = surgeonsKnot(links);
  RecognitionMeasure m;
  KnotTracker tracker;
  double all = 0.0;
  double steady = 0.0;
  for (int k = 0; k < steps; ++k) {
    // a rigid drift and turn: every node moves more than the move tolerance
    const Eigen::AngleAxisd turn(0.002 * k, Vec3::UnitZ());
    const Points x = ((turn.toRotationMatrix() * knot).colwise() + Vec3(0.02 * k, 0.0, 0.0)).eval();
    const int searchedBefore = tracker.searches();
    const double start = cpuSeconds();
    tracker.update(k, x, {}, {});
    const double spent = cpuSeconds() - start;
    all += spent;
    if (tracker.searches() == searchedBefore) steady += spent;
    // the tracker confirms a reading on its second step
    if (k >= 1) {
      ++m.steps;
      m.right += isSurgeonsOfTwo(tracker.reading()) ? 1 : 0;
    }
  }
  m.searches = tracker.searches();
  m.meanUs = 1e6 * all / steps;
  m.steadyUs = 1e6 * steady / std::max(1, steps - m.searches);

  const int searches = std::max(3, steps / 10);
  double search = 0.0;
  for (int k = 0; k < searches; ++k) {
    const double start = cpuSeconds();
    const KnotReading r = recogniseKnot(knot, {});
    search += cpuSeconds() - start;
    ++m.steps;
    m.right += isSurgeonsOfTwo(r) ? 1 : 0;
  }
  m.searchUs = 1e6 * search / searches;
  return m;
}

struct TightMeasure {
  double stepUs = 0.0;      // mean over the held steps
  double maxStretch = 0.0;  // over the whole pull
  double pulledMm = 0.0;    // how far each end was drawn before the thread came taut
  bool taut = false;        // it did (a link stretched past the tracker's tightStrain)
  int tightened = 0;        // KnotTightened events the tracker gave
  int right = 0;
  int steps = 0;
  int breaks = 0;
};

TightMeasure measureTightKnot(int links, int maxPullSteps, int heldSteps) {
  // the double throw at the stitch, in equal links, its pierces where the builder put them
  const knot_test::ThreadBuilder tied = knot_test::stitchTwist(2.0, false);
  const Points shape = tied.points();
  std::vector<double> arc(static_cast<std::size_t>(shape.cols()), 0.0);
  for (Eigen::Index i = 1; i < shape.cols(); ++i)
    arc[static_cast<std::size_t>(i)] =
        arc[static_cast<std::size_t>(i - 1)] + (shape.col(i) - shape.col(i - 1)).norm();
  const Points x0 = knot_test::evenlySpaced(shape, 1.0, links);

  SutureDef def;
  def.links = links;
  def.needleLinks = 0;
  def.length = knot_test::polylineLength(x0);
  const SutureModel model(def);
  SutureState state = SutureState::laidOut(model);
  state.x = x0;
  state.xPrev = x0;
  std::vector<int> anchors;
  for (const int a : tied.anchors()) {
    const auto node =
        static_cast<int>(std::lround(arc[static_cast<std::size_t>(a)] / arc.back() * links));
    anchors.push_back(node);
    Pierce p;
    p.face = 0;
    p.node = node;
    p.point = x0.col(node);
    state.pierces.push_back(p);
  }

  auto solver = makeSutureSolver("direct");
  const SutureStepParams params;
  const SutureWorld world;
  const KnotTrackerDef trackerDef;
  KnotTracker tracker(trackerDef);
  const Vec3 out0 = (x0.col(0) - x0.col(links / 2)).normalized();
  const Vec3 out1 = (x0.col(links) - x0.col(links / 2)).normalized();
  TightMeasure m;
  double held = 0.0;
  int heldSoFar = 0;
  // drawn 0.01 mm a step each end until the thread is taut, then held there
  for (int k = 0; heldSoFar < heldSteps && k < maxPullSteps + heldSteps; ++k) {
    if (!m.taut) m.pulledMm = 0.01 * k;
    const Grip grips[2] = {{0, x0.col(0) + m.pulledMm * out0},
                           {links, x0.col(links) + m.pulledMm * out1}};
    const double start = cpuSeconds();
    const SutureStepReport r = solver->step(model, state, grips, world, params);
    if (m.taut) {
      held += cpuSeconds() - start;
      ++heldSoFar;
    }
    m.maxStretch = std::max(m.maxStretch, r.maxStretch);
    m.taut = m.taut || r.maxStretch >= trackerDef.tightStrain || k >= maxPullSteps;
    for (const SutureEvent& e : r.events) m.breaks += e.kind == SutureEventKind::Break ? 1 : 0;
    for (const KnotEvent& e : tracker.update(k, state.x, anchors, linkStretches(model, state)))
      m.tightened += e.kind == KnotEventKind::KnotTightened ? 1 : 0;
    if (k >= 1) {
      ++m.steps;
      m.right += isDoubleThrow(tracker.reading()) ? 1 : 0;
    }
  }
  m.taut = m.maxStretch >= trackerDef.tightStrain;
  m.stepUs = 1e6 * held / std::max(1, heldSoFar);
  return m;
}

BenchRow knotRow(const std::string& caseName, const std::string& metric, double value,
                 const char* unit, std::optional<double> goal = std::nullopt) {
  BenchRow r{"suture", caseName, metric, value, unit, std::nullopt, std::nullopt, std::nullopt};
  if (goal) r.ratio = value / *goal;
  return r;
}

}  // namespace

void appendKnotRows(BenchReport& report, const BenchOptions& options, BenchProgress& progress) {
  const std::vector<int> sizes =
      options.quick ? std::vector<int>{60, 200} : std::vector<int>{60, 200, 2000};
  const int steps = options.quick ? 20 : 200;
  for (const int n : sizes) {
    const std::string name = "knot recognition, surgeon's knot, " + std::to_string(n) + " links";
    progress.next(name);
    const RecognitionMeasure m = measureRecognition(n, steps);
    const std::optional<double> goal =
        n == 200 ? std::optional<double>(kRecognitionGoalUs) : std::nullopt;
    const std::string goalText = n == 200 ? " (goal <= 20 us; ratio = ours / goal)" : "";
    report.rows.push_back(knotRow(name, "step from the last picture, thread moving" + goalText,
                                  m.steadyUs, "us", goal));
    report.rows.push_back(knotRow(name, "mean step, searches included", m.meanUs, "us"));
    report.rows.push_back(knotRow(name, "full search, every direction", m.searchUs, "us"));
    report.rows.push_back(
        knotRow(name, "steps that searched", static_cast<double>(m.searches), "steps"));
    report.rows.push_back(knotRow(name, "read right (surgeon's, 2 throws)",
                                  100.0 * m.right / std::max(1, m.steps), "% of steps"));
  }

  const std::string tight = "double throw at a stitch pulled tight, 200 links [direct]";
  progress.next(tight);
  const TightMeasure t =
      measureTightKnot(200, options.quick ? 300 : 1000, options.quick ? 20 : 200);
  report.rows.push_back(
      knotRow(tight, "suture step, knot pulled tight (goal <= 200 us; ratio = ours / goal)",
              t.stepUs, "us", kTightStepGoalUs));
  report.rows.push_back(knotRow(tight, "each end drawn until taut", t.pulledMm, "mm"));
  report.rows.push_back(knotRow(tight, "max stretch while tightening", t.maxStretch, "relative"));
  report.rows.push_back(
      knotRow(tight, "knot tightened events", static_cast<double>(t.tightened), "events"));
  report.rows.push_back(knotRow(tight, "breaks", static_cast<double>(t.breaks), "events"));
  report.rows.push_back(knotRow(tight, "read right (one throw, 2 wraps)",
                                100.0 * t.right / std::max(1, t.steps), "% of steps"));
}

}  // namespace microsim::bench
