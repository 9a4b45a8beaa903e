// The scene's knot reading: the thread, as a step left it, handed to the knot tracker, and what
// the tracker reports made scene events (scene.h, suture/knot_tracker.h).
#include "microsim/sim/scene/scene.h"

#include <algorithm>

namespace microsim::sim {

namespace {

SceneEventKind sceneEventKindOf(suture::KnotEventKind kind) {
  switch (kind) {
    case suture::KnotEventKind::ThrowFormed:
      return SceneEventKind::ThrowFormed;
    case suture::KnotEventKind::KnotTightened:
      return SceneEventKind::KnotTightened;
    case suture::KnotEventKind::KnotSlipped:
      return SceneEventKind::KnotSlipped;
  }
  return SceneEventKind::ThrowFormed;
}

// the piece of the chain the stitch is tied on: the one holding the most pierces, else the
// longest (a cut or a break splits the chain; a knot lies in one piece)
suture::Piece knotPiece(const suture::SutureState& s) {
  const std::vector<suture::Piece> pieces = suture::chainPieces(s.alive);
  suture::Piece best = pieces.front();
  int bestPierces = -1;
  for (const suture::Piece& piece : pieces) {
    const auto pierced = static_cast<int>(std::count_if(
        s.pierces.begin(), s.pierces.end(),
        [&](const suture::Pierce& p) { return p.node >= piece.first && p.node <= piece.last; }));
    const bool longer = piece.last - piece.first > best.last - best.first;
    if (pierced > bestPierces || (pierced == bestPierces && longer)) {
      best = piece;
      bestPierces = pierced;
    }
  }
  return best;
}

}  // namespace

void Scene::readKnots() {
  const suture::SutureModel& model = *suture_;
  const suture::SutureState& s = sutureState_;

  // the anchors are the pierces only: the recogniser reads the stretch between the first and the
  // last anchor as the stitch in the tissue, so a grip counted as one would hide the knot
  // between the hands
  const suture::Piece piece = knotPiece(s);
  knotAnchors_.clear();
  for (const suture::Pierce& p : s.pierces)
    if (p.node >= piece.first && p.node <= piece.last) knotAnchors_.push_back(p.node - piece.first);
  std::sort(knotAnchors_.begin(), knotAnchors_.end());
  knotAnchors_.erase(std::unique(knotAnchors_.begin(), knotAnchors_.end()), knotAnchors_.end());

  const std::vector<double> stretch = suture::linkStretches(model, s);
  knotStretch_.assign(stretch.begin() + piece.first, stretch.begin() + piece.last);

  // the whole chain is read in place; a piece of it is copied
  const bool whole = piece.first == 0 && piece.last == model.nodeCount() - 1;
  if (!whole) knotNodes_ = s.x.middleCols(piece.first, piece.last - piece.first + 1);
  const std::span<const suture::KnotEvent> found =
      knots_->update(steps_, whole ? s.x : knotNodes_, knotAnchors_, knotStretch_);

  // a knot tightened round the stitch's holes pulls them; its turns' length is taken as it
  // tightens, and kept while it holds
  const suture::KnotReading& knot = knots_->reading();
  const bool overStitch = knots_->tightened() && !knot.throws.empty() && !knotAnchors_.empty() &&
                          knot.throws.front().first < knotAnchors_.front() &&
                          knot.throws.front().last > knotAnchors_.back();
  if (overStitch) {
    const double first = knot.throws.front().first + piece.first;
    const double last = knot.throws.front().last + piece.first;
    const double wrap =
        knotOverStitch_ ? knotOverStitch_->wrap : suture::knotWrap(model, s, first, last);
    knotOverStitch_ = suture::KnotOverStitch{first, last, wrap};
  } else {
    knotOverStitch_.reset();
  }

  for (const suture::KnotEvent& k : found) {
    const SceneEventKind kind = sceneEventKindOf(k.kind);
    addEvent(kind, -1, kind == SceneEventKind::ThrowFormed ? k.throwIndex : -1, k.throws);
    SceneEvent& e = events_.back();
    e.value = k.tension;
    e.knot.type = k.type;
    e.knot.handedness = k.handedness;
    e.knot.wraps = k.wraps;
    e.knot.slide = k.slide;
    e.knot.cause = k.cause;
  }
}

}  // namespace microsim::sim
