#include "microsim/assessment/scoring/metrics.h"
#include "scoring/not_measured.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace microsim::assessment {

namespace {

constexpr std::array<MetricInfo, 36> kCatalogue{{
    {"time", "s"},
    {"path_length", "mm"},
    {"path_length_left", "mm"},
    {"path_length_right", "mm"},
    {"movements", "count"},
    {"smoothness", "1"},
    {"idle_time", "s"},
    {"regrasps", "count"},
    {"suture_breaks", "count"},
    {"max_stretch", "1"},
    {"tissue_damage", "count"},
    {"passages", "count"},
    {"arc_deviation", "mm"},
    {"entry_angle", "deg"},
    {"exit_angle", "deg"},
    {"bite", "mm"},
    {"bite_walls", "1"},
    {"full_thickness", "1"},
    {"back_wall_catches", "count"},
    {"stitches", "count"},
    {"bite_symmetry", "mm"},
    {"spacing", "deg"},
    {"triangulation_error", "deg"},
    {"lapse_index", "count"},
    {"oblique_stitches", "count"},
    {"partial_thickness_bites", "count"},
    {"wide_bites", "count"},
    {"unequal_spacing", "count"},
    {"knots_tied", "count"},
    {"secure_knots", "count"},
    {"knots_slipped", "count"},
    {"knot_throws", "count"},
    {"thread_cuts", "count"},
    {"cut_end_length", "mm"},
    {"leaks", "count"},
    {"leak_gap", "mm"},
}};

// mean of the finite values `get` picks; NaN when there are none
template <typename T, typename Get>
double meanOf(const std::vector<T>& items, Get get) {
  double sum = 0.0;
  int n = 0;
  for (const T& item : items) {
    const double v = get(item);
    if (!std::isfinite(v)) continue;
    sum += v;
    ++n;
  }
  return n > 0 ? sum / n : kNaN;
}

int countEvents(const std::vector<sim::SceneEvent>& events,
                std::initializer_list<sim::SceneEventKind> kinds) {
  return static_cast<int>(std::count_if(events.begin(), events.end(), [&](const auto& e) {
    return std::find(kinds.begin(), kinds.end(), e.kind) != kinds.end();
  }));
}

// TissueOverStretch and TissueTear events, once the scene reports them (they are being
// appended to SceneEventKind); until then the count is 0 and max_stretch carries the damage
template <typename Kind = sim::SceneEventKind>
int tissueDamageEvents(const std::vector<sim::SceneEvent>& events) {
  if constexpr (requires { Kind::TissueOverStretch; Kind::TissueTear; })
    return countEvents(events, {Kind::TissueOverStretch, Kind::TissueTear});
  else
    return 0;
}

}  // namespace

std::span<const MetricInfo> metricCatalogue() { return kCatalogue; }

const MetricInfo* findMetric(std::string_view key) {
  for (const MetricInfo& m : kCatalogue)
    if (m.key == key) return &m;
  return nullptr;
}

std::optional<double> AttemptMetrics::value(std::string_view key) const {
  for (const MetricValue& v : values)
    if (v.key == key) return v.value;
  return std::nullopt;
}

AttemptMetrics computeMetrics(const Attempt& attempt, const MotionParams& params) {
  using K = sim::SceneEventKind;
  AttemptMetrics m;
  m.pierces = pierceMetrics(attempt);
  m.stitches = stitchMetrics(m.pierces);
  for (int h = 0; h < sim::kHandCount; ++h)
    m.hands[static_cast<std::size_t>(h)] =
        handMotion(attempt.motion[static_cast<std::size_t>(h)], attempt.stepDt, params);

  // motion of both hands
  std::vector<Movement> movements;
  for (const HandMotion& h : m.hands)
    movements.insert(movements.end(), h.movements.begin(), h.movements.end());
  const double left = m.hands[0].pathLengthMm;
  const double right = m.hands[1].pathLengthMm;

  // pierces and stitches
  const auto& p = m.pierces;
  const double fullThickness =
      p.empty() ? kNaN
                : static_cast<double>(std::count_if(p.begin(), p.end(),
                                                    [](const auto& x) { return x.fullThickness; })) /
                      static_cast<double>(p.size());
  const double backWall = static_cast<double>(
      std::count_if(p.begin(), p.end(), [](const auto& x) { return x.backWall; }));
  const std::optional<double> triangulation = triangulationErrorDeg(m.stitches);
  m.endProduct = endProductErrors(attempt);
  const KnotSummary knots = knotSummary(attempt.events);
  const bool leakVerdict = attempt.leak && attempt.leak->status == sim::LeakTestStatus::Solved;
  const auto lapseCount = [&](EndProductErrorKind kind) {
    return static_cast<double>(countEndProductErrors(m.endProduct, kind));
  };

  const std::array<double, kCatalogue.size()> values{
      attempt.duration,
      left + right,
      left,
      right,
      static_cast<double>(movements.size()),
      meanOf(movements, [](const Movement& x) { return x.ldlj; }),
      idleTime(attempt, params),
      static_cast<double>(regrasps(attempt.events)),
      static_cast<double>(countEvents(attempt.events, {K::SutureBreak})),
      attempt.maxStretch,
      static_cast<double>(tissueDamageEvents(attempt.events)),
      static_cast<double>(p.size()),
      needleArcDeviationMm(attempt),
      meanOf(p, [](const PierceMetrics& x) { return x.entryAngleDeg; }),
      meanOf(p, [](const PierceMetrics& x) { return x.exitAngleDeg; }),
      meanOf(p, [](const PierceMetrics& x) { return x.biteMm; }),
      meanOf(p, [](const PierceMetrics& x) { return x.biteWalls; }),
      fullThickness,
      backWall,
      static_cast<double>(m.stitches.size()),
      meanOf(m.stitches, [](const StitchMetrics& x) { return x.symmetryMm; }),
      meanOf(m.stitches, [](const StitchMetrics& x) { return x.spacingDeg; }),
      triangulation ? *triangulation : kNaN,
      static_cast<double>(m.endProduct.size()),
      lapseCount(EndProductErrorKind::ObliqueStitch),
      lapseCount(EndProductErrorKind::PartialThicknessBite),
      lapseCount(EndProductErrorKind::WideBite),
      lapseCount(EndProductErrorKind::UnequalSpacing),
      static_cast<double>(knots.tightened),
      static_cast<double>(knots.secure),
      static_cast<double>(knots.slipped),
      knots.meanThrows,
      static_cast<double>(knots.cuts),
      knots.meanCutEndMm,
      leakVerdict ? (attempt.leak->leaks ? 1.0 : 0.0) : kNaN,
      leakVerdict ? attempt.leak->largestGapMm : kNaN,
  };
  m.values.reserve(kCatalogue.size());
  for (std::size_t i = 0; i < kCatalogue.size(); ++i)
    m.values.push_back({std::string(kCatalogue[i].key), values[i], std::string(kCatalogue[i].unit)});

  // stepped input: its finite differences measure the steps, not the hand
  if (steppedInput(attempt))
    for (MetricValue& v : m.values)
      if (v.key == "smoothness" || v.key == "idle_time") {
        v.value = kNaN;
        v.applicable = false;
      }
  return m;
}

}  // namespace microsim::assessment
