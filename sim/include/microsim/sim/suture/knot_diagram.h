#pragma once
// The thread seen from one direction: a knot diagram (issue 19, item 2).
//
// A knot is read from a picture of the thread: project the polyline along a view direction d,
// find where the picture crosses itself, and note at each crossing which strand is on top (the
// one nearer the eye, larger x·d) and the crossing's sign. Walking the curve from one end to the
// other and writing down each crossing as it is passed, over or under, gives the Gauss word;
// with the signs it determines the knot, and Reidemeister moves on it (knot_simplify.h) remove
// crossings that tie nothing.
//
// Open thread. A knot in an open arc is only defined once the ends are joined; the standard
// closure, and the one a surgeon means, joins them far outside: each end is extended in the
// picture straight away from the curve's centre to a circle around the whole picture, above
// everything else (so it passes over any strand it meets), and the two points on the circle are
// joined along it, where nothing crosses. A crossing with an extension is kept in the word (it
// is part of the closed diagram); views whose extensions cross nothing are preferred.
//
// Anchors. Nodes where the thread is held — its pierces through the tissue, a tool's grip — are
// written into the word as anchor marks. The thread cannot be turned about an anchor, so no
// Reidemeister move may pass one: a twist of the two strands next to a stitch is a throw, not a
// kink to undo.
//
// Sign. With the over strand's direction o, the under strand's u and d pointing to the eye, the
// sign is sign((o × u)·d): +1 is a right-handed (positive) crossing, −1 a left-handed one. It
// does not change when the whole curve is walked the other way.
//
// Quality. A picture can hide or invent structure: two strands that cross at a grazing angle,
// three strands through one point, a strand seen end-on (a crossing at the tip of a segment
// whose picture has almost no length). `quality` in [0, 1] is the worst of those margins over
// every crossing, each scaled so that 1 is comfortably clear; the recogniser (knot_recognition.h)
// looks from several directions and keeps the clearest picture.
//
// Cost: a sweep over the segments' extents along the picture's long axis (its principal
// direction), so O(n log n) for n links plus the pairs that overlap along it — the knot's own
// neighbourhood, not the whole thread.
//
// Units: millimetres; curve parameters are segment index + fraction (the start's extension has
// parameters in [−1, 0), the end's in [m − 1, m) for m nodes).

#include "microsim/sim/suture/suture_model.h"

#include <span>
#include <vector>

namespace microsim::sim::suture {

/// One crossing of the picture with itself.
struct KnotCrossing {
  double overAt = 0.0;   ///< curve parameter of the strand on top
  double underAt = 0.0;  ///< curve parameter of the strand below
  int sign = 0;          ///< +1 right-handed (positive), −1 left-handed
  bool withClosure = false;  ///< one of the two strands is an end's extension to the far circle
};

/// One passage in the Gauss word: a crossing passed over or under, or an anchor.
struct GaussEntry {
  int crossing = -1;  ///< index into KnotDiagram::crossings; −1 for an anchor
  bool over = false;  ///< the curve passes on top here
  double at = 0.0;    ///< curve parameter
};

struct KnotDiagram {
  Vec3 direction = Vec3::UnitZ();       ///< toward the eye (unit)
  std::vector<KnotCrossing> crossings;
  std::vector<GaussEntry> word;         ///< passages and anchors in curve order (start's extension first)
  double quality = 1.0;                 ///< 0..1, see the header
  int closureCrossings = 0;             ///< crossings with an end's extension
};

/// The picture of `x` (3 by m, m ≥ 2) seen along `direction` (need not be unit), its ends joined
/// far outside, with the nodes in `anchors` marked in the word.
KnotDiagram projectKnot(const Points& x, std::span<const int> anchors, const Vec3& direction);

/// Directions to look from (unit): the three principal axes of the curve's points, smallest
/// spread first, then the six face and four body diagonals of that frame. They turn with the
/// curve, so a rigid rotation of the thread is seen the same way.
std::vector<Vec3> knotViewDirections(const Points& x);

}  // namespace microsim::sim::suture
