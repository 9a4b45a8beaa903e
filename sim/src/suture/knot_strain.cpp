#include "microsim/sim/suture/knot_strain.h"

#include "microsim/sim/collide/segment_segment.h"
#include "microsim/sim/suture/suture_constraints.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace microsim::sim::suture {

namespace {

// Whether another strand (a link at least `skip` along the chain) lies against link l from
// the side, as in a knot: its nearest point within 1.5 diameters, off the link's own line by
// more than 60°. A thread pushed shorter along a straight line folds onto its own line, where
// the self-contact pushes overlapping links along it; that stretches links too, and no knot
// is there.
bool pressedFromTheSide(const Points& x, const std::vector<std::uint8_t>& alive, int l, int skip,
                        double gap) {
  const Vec3 a = x.col(l);
  const Vec3 b = x.col(l + 1);
  const Vec3 along = (b - a).normalized();
  const int links = static_cast<int>(alive.size());
  for (int j = 0; j < links; ++j) {
    if (std::abs(j - l) < skip || alive[static_cast<std::size_t>(j)] == 0) continue;
    const collide::SegmentClosest c = collide::closestSegmentSegment(a, b, x.col(j), x.col(j + 1));
    if (!(c.distance < 1.5 * gap)) continue;
    const Vec3 apart = c.onSecond - c.onFirst;
    if (apart.norm() > 0.0 && std::abs(apart.normalized().dot(along)) < 0.5) return true;
  }
  return false;
}

}  // namespace

std::optional<int> findKnotBreak(const SutureModel& model, SutureState& state,
                                 std::span<const Grip> grips, std::span<const std::uint8_t> pressed,
                                 int skip, double seconds) {
  const int links = model.linkCount();
  state.heldPastBreak.resize(static_cast<std::size_t>(links), 0.0);

  // a thread link's stretch when it is pressed on and past the limit, else 0: nearly every
  // substep has none, and then nothing more is looked at (the needle is rigid: only thread
  // links break)
  const double limit = 1.0 + model.def().knotBreakStretch;
  const auto overStretched = [&](int l) {
    const auto at = static_cast<std::size_t>(l);
    if (l < model.swage() || state.alive[at] == 0 || (pressed[at] == 0 && pressed[at + 1] == 0)) return 0.0;
    const double stretch = (state.x.col(l + 1) - state.x.col(l)).norm() / model.rest(l);
    return stretch > limit ? stretch : 0.0;
  };
  bool any = false;
  for (int l = model.swage(); l < links && !any; ++l) any = overStretched(l) > 0.0;
  if (!any) {
    std::fill(state.heldPastBreak.begin(), state.heldPastBreak.end(), 0.0);
    return std::nullopt;
  }

  // of those, the ones something pulls from both sides (between a piece's first and last grip
  // or pierce) with another strand against them from the side
  std::vector<std::uint8_t> pulled(static_cast<std::size_t>(links), 0);
  for (const Piece& piece : chainPieces(state.alive)) {
    const std::vector<ChainConstraint> cs = pieceConstraints(model, state, grips, piece);
    if (cs.size() < 2) continue;
    for (int l = cs.front().node; l < cs.back().node; ++l) pulled[static_cast<std::size_t>(l)] = 1;
  }
  std::optional<int> worst;
  double worstStretch = 0.0;
  for (int l = 0; l < links; ++l) {
    const auto at = static_cast<std::size_t>(l);
    double& held = state.heldPastBreak[at];
    const double stretch = pulled[at] != 0 ? overStretched(l) : 0.0;
    if (stretch == 0.0 ||
        !pressedFromTheSide(state.x, state.alive, l, skip, 2.0 * model.def().contactRadius)) {
      held = 0.0;
      continue;
    }
    held += seconds;
    if (held >= kKnotBreakSeconds && stretch > worstStretch) {
      worstStretch = stretch;
      worst = l;
    }
  }
  // the break lets the knot's tension go: every hold starts again
  if (worst) std::fill(state.heldPastBreak.begin(), state.heldPastBreak.end(), 0.0);
  return worst;
}

}  // namespace microsim::sim::suture
