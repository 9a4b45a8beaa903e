#include "microsim/assessment/scoring/end_product.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

namespace microsim::assessment {

namespace {

using LapseKind = EndProductErrorKind;

constexpr std::array<LapseKind, 10> kEndProductKinds{
    LapseKind::SutureLineDisruption,
    LapseKind::BackWallStitch,
    LapseKind::ObliqueStitch,
    LapseKind::WideBite,
    LapseKind::PartialThicknessBite,
    LapseKind::UnequalSpacing,
    LapseKind::WallTear,
    LapseKind::OverTightStitch,
    LapseKind::ThreadInLumen,
    LapseKind::LargeEdgeOverlap,
};

// what the end-product check reads of an attempt: its passages and stitches, which of them
// the thread runs through, and which stitch each passage is part of
struct EndProductView {
  std::vector<PierceMetrics> passages;
  std::vector<StitchMetrics> stitches;
  std::vector<int> stitchOfPassage;  ///< parallel to passages, -1 outside a stitch
  std::vector<bool> inProduct;       ///< parallel to passages: the thread reached its holes
};

EndProductView endProductView(const Attempt& attempt) {
  EndProductView v;
  v.passages = pierceMetrics(attempt);
  v.stitches = stitchMetrics(v.passages);
  v.stitchOfPassage.assign(v.passages.size(), -1);
  for (std::size_t s = 0; s < v.stitches.size(); ++s) {
    v.stitchOfPassage[static_cast<std::size_t>(v.stitches[s].first)] = static_cast<int>(s);
    v.stitchOfPassage[static_cast<std::size_t>(v.stitches[s].second)] = static_cast<int>(s);
  }

  // holes the needle left before the thread reached them
  std::set<int> released;
  for (const sim::SceneEvent& e : attempt.events)
    if (e.kind == sim::SceneEventKind::PierceReleased) released.insert(e.index);
  v.inProduct.reserve(v.passages.size());
  for (const PierceMetrics& p : v.passages)
    v.inProduct.push_back(!released.contains(p.entry) && !released.contains(p.exit));
  return v;
}

bool stitchInProduct(const EndProductView& v, const StitchMetrics& s) {
  return v.inProduct[static_cast<std::size_t>(s.first)] &&
         v.inProduct[static_cast<std::size_t>(s.second)];
}

// the passage whose entry or exit is pierce event `pierce`; -1 if none
int passageOfPierce(const std::vector<PierceMetrics>& passages, int pierce) {
  for (std::size_t i = 0; i < passages.size(); ++i)
    if (passages[i].entry == pierce || passages[i].exit == pierce) return static_cast<int>(i);
  return -1;
}

void addPassageErrors(const EndProductView& v, const EndProductLimits& limits,
                      std::vector<EndProductError>& out) {
  for (std::size_t i = 0; i < v.passages.size(); ++i) {
    if (!v.inProduct[i]) continue;
    const PierceMetrics& p = v.passages[i];
    EndProductError e;
    e.stitch = v.stitchOfPassage[i];
    e.passage = static_cast<int>(i);
    e.angleDeg = p.circumferenceDeg;
    if (p.backWall) {
      e.kind = LapseKind::BackWallStitch;
      out.push_back(e);
    }
    // a passage still in the wall is not a bite yet
    if (p.exit >= 0 && !p.fullThickness) {
      e.kind = LapseKind::PartialThicknessBite;
      out.push_back(e);
    }
    if (std::isfinite(p.biteWalls) && p.biteWalls > limits.wideBiteWalls) {
      e.kind = LapseKind::WideBite;
      e.measured = p.biteWalls;
      e.limit = limits.wideBiteWalls;
      out.push_back(e);
    }
  }
}

void addObliqueStitches(const EndProductView& v, const EndProductLimits& limits,
                        std::vector<EndProductError>& out) {
  for (std::size_t s = 0; s < v.stitches.size(); ++s) {
    const StitchMetrics& st = v.stitches[s];
    if (!stitchInProduct(v, st)) continue;
    const double a = v.passages[static_cast<std::size_t>(st.first)].circumferenceDeg;
    const double b = v.passages[static_cast<std::size_t>(st.second)].circumferenceDeg;
    const double skew = angularDistanceDeg(a, b);
    if (!(skew > limits.obliqueDeg)) continue;
    EndProductError e;
    e.kind = LapseKind::ObliqueStitch;
    e.stitch = static_cast<int>(s);
    e.angleDeg = st.positionDeg;
    e.measured = skew;
    e.limit = limits.obliqueDeg;
    out.push_back(e);
  }
}

// the gaps between neighbouring stitches of each vessel, sorted around the circle
void addUnequalSpacing(const EndProductView& v, const EndProductLimits& limits,
                       std::vector<EndProductError>& out) {
  std::set<int> objects;
  for (const StitchMetrics& st : v.stitches)
    objects.insert(v.passages[static_cast<std::size_t>(st.first)].object);
  for (int object : objects) {
    // this vessel's stitches in the product, by position
    std::vector<int> ring;
    for (std::size_t s = 0; s < v.stitches.size(); ++s) {
      const StitchMetrics& st = v.stitches[s];
      if (stitchInProduct(v, st) && std::isfinite(st.positionDeg) &&
          v.passages[static_cast<std::size_t>(st.first)].object == object)
        ring.push_back(static_cast<int>(s));
    }
    if (ring.size() < 3) continue;
    const auto position = [&](int s) {
      return v.stitches[static_cast<std::size_t>(s)].positionDeg;
    };
    std::stable_sort(ring.begin(), ring.end(),
                     [&](int a, int b) { return position(a) < position(b); });

    // each gap against the mean, 360° / stitches
    const double mean = 360.0 / static_cast<double>(ring.size());
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const double from = position(ring[k]);
      const double to = position(ring[(k + 1) % ring.size()]);
      const double gap = k + 1 < ring.size() ? to - from : to + 360.0 - from;
      const double deviation = std::abs(gap - mean) / mean;
      if (!(deviation > limits.unequalSpacingFraction)) continue;
      EndProductError e;
      e.kind = LapseKind::UnequalSpacing;
      e.stitch = ring[k];
      e.angleDeg = std::fmod(from + 0.5 * gap, 360.0);
      e.measured = deviation;
      e.limit = limits.unequalSpacingFraction;
      out.push_back(e);
    }
  }
}

void addEventErrors(const Attempt& attempt, const EndProductView& v,
                    std::vector<EndProductError>& out) {
  using K = sim::SceneEventKind;
  for (std::size_t i = 0; i < attempt.events.size(); ++i) {
    const sim::SceneEvent& ev = attempt.events[i];
    EndProductError e;
    e.event = static_cast<int>(i);
    switch (ev.kind) {
      case K::TissueTear:
        e.kind = LapseKind::WallTear;
        e.measured = ev.count;  // links torn
        break;
      case K::SutureBreak:
        e.kind = LapseKind::SutureLineDisruption;
        break;
      case K::SuturePulledOut: {
        // where the thread slid out: the passage of that hole
        e.kind = LapseKind::SutureLineDisruption;
        e.passage = passageOfPierce(v.passages, ev.index);
        if (e.passage >= 0) {
          e.stitch = v.stitchOfPassage[static_cast<std::size_t>(e.passage)];
          e.angleDeg = v.passages[static_cast<std::size_t>(e.passage)].circumferenceDeg;
        }
        break;
      }
      default:
        continue;
    }
    out.push_back(e);
  }
}

// what the final scene showed (sim/scene/end_state_check.h), in the check's order
void addEndStateErrors(const Attempt& attempt, std::vector<EndProductError>& out) {
  if (!attempt.endState) return;
  for (const sim::EndStateFinding& f : attempt.endState->findings) {
    EndProductError e;
    switch (f.kind) {
      case sim::EndStateKind::OverTightStitch:
        e.kind = LapseKind::OverTightStitch;
        break;
      case sim::EndStateKind::ThreadInLumen:
        e.kind = LapseKind::ThreadInLumen;
        break;
      case sim::EndStateKind::LargeEdgeOverlap:
        e.kind = LapseKind::LargeEdgeOverlap;
        break;
    }
    e.angleDeg = f.angleDeg;
    e.measured = f.measured;
    e.limit = f.limit;
    out.push_back(e);
  }
}

}  // namespace

std::span<const EndProductErrorKind> endProductErrorKinds() {
  return kEndProductKinds;
}

std::string_view endProductErrorKey(EndProductErrorKind kind) {
  switch (kind) {
    case LapseKind::SutureLineDisruption:
      return "suture_line_disruption";
    case LapseKind::BackWallStitch:
      return "back_wall_stitch";
    case LapseKind::ObliqueStitch:
      return "oblique_stitch";
    case LapseKind::WideBite:
      return "wide_bite";
    case LapseKind::PartialThicknessBite:
      return "partial_thickness_bite";
    case LapseKind::UnequalSpacing:
      return "unequal_spacing";
    case LapseKind::WallTear:
      return "wall_tear";
    case LapseKind::OverTightStitch:
      return "over_tight_stitch";
    case LapseKind::ThreadInLumen:
      return "thread_in_lumen";
    case LapseKind::LargeEdgeOverlap:
      return "large_edge_overlap";
  }
  return "";
}

std::optional<EndProductErrorKind> endProductErrorKindFromKey(std::string_view key) {
  const auto kinds = endProductErrorKinds();
  const auto it = std::find_if(kinds.begin(), kinds.end(), [key](EndProductErrorKind k) {
    return endProductErrorKey(k) == key;
  });
  return it == kinds.end() ? std::nullopt : std::optional<EndProductErrorKind>(*it);
}

std::string_view endProductErrorUnit(EndProductErrorKind kind) {
  switch (kind) {
    case LapseKind::SutureLineDisruption:
      return "mm";  // a leak's largest gap
    case LapseKind::ObliqueStitch:
      return "deg";
    case LapseKind::WideBite:
      return "walls";
    case LapseKind::UnequalSpacing:
    case LapseKind::OverTightStitch:
      return "1";
    case LapseKind::ThreadInLumen:
    case LapseKind::LargeEdgeOverlap:
      return "mm";
    case LapseKind::WallTear:
      return "count";
    case LapseKind::BackWallStitch:
    case LapseKind::PartialThicknessBite:
      return "";
  }
  return "";
}

std::vector<EndProductError> endProductErrors(const Attempt& attempt,
                                              const std::optional<LeakFinding>& leak,
                                              const EndProductLimits& limits) {
  const EndProductView v = endProductView(attempt);
  std::vector<EndProductError> out;
  addPassageErrors(v, limits, out);
  addObliqueStitches(v, limits, out);
  addUnequalSpacing(v, limits, out);
  addEventErrors(attempt, v, out);
  addEndStateErrors(attempt, out);

  // the pressure test: the line leaks at its largest gap
  if (leak && leak->leaks) {
    EndProductError e;
    e.kind = LapseKind::SutureLineDisruption;
    e.angleDeg = leak->angleDeg;
    e.measured = leak->largestGapMm;
    e.limit = leak->limitMm;
    out.push_back(e);
  }
  return out;
}

int countEndProductErrors(const std::vector<EndProductError>& errors, EndProductErrorKind kind) {
  return static_cast<int>(std::count_if(
      errors.begin(), errors.end(), [kind](const EndProductError& e) { return e.kind == kind; }));
}

}  // namespace microsim::assessment
