#include "microsim/assessment/scoring/knot_metrics.h"

#include <algorithm>

namespace microsim::assessment {

bool knotTypeLocks(sim::suture::KnotType type) {
  return type == sim::suture::KnotType::Square || type == sim::suture::KnotType::Surgeons;
}

KnotSummary knotSummary(const std::vector<sim::SceneEvent>& events) {
  using K = sim::SceneEventKind;
  KnotSummary s;
  int throws = 0;
  double cutEnds = 0.0;
  // the latest tightened knot counts as secure until a slip says otherwise
  bool latestSecure = false;
  for (const sim::SceneEvent& e : events) {
    switch (e.kind) {
      case K::KnotTightened:
        if (latestSecure) ++s.secure;
        ++s.tightened;
        throws += e.count;
        latestSecure = knotTypeLocks(e.knot.type) && e.count >= 2;
        break;
      case K::KnotSlipped:
        ++s.slipped;
        latestSecure = false;
        break;
      case K::ThreadCut:
        if (e.value < 0.0) break;
        ++s.cuts;
        cutEnds += e.value;
        s.longestCutEndMm = s.cuts == 1 ? e.value : std::max(s.longestCutEndMm, e.value);
        break;
      default:
        break;
    }
  }
  if (latestSecure) ++s.secure;
  if (s.tightened > 0) s.meanThrows = static_cast<double>(throws) / s.tightened;
  if (s.cuts > 0) s.meanCutEndMm = cutEnds / s.cuts;
  return s;
}

}  // namespace microsim::assessment
