#pragma once
// The finished anastomosis looked at (issue 19, item 5): three lapses of the Anastomosis Lapse
// Index (Ghanem et al., J Reconstr Microsurg 2016; assessment's scoring/end_product.h) that only
// the final scene shows, each measured, located and held against a limit. The leak test
// (scene/leak_test.h) is the fourth look at the final scene; this one solves nothing: it
// reads the tissue and the thread as the attempt left them.
//
// Over-tight stitch. A stitch's loop encloses a bite of each end: the wall from each hole to
// its end's cut edge. Tied to bring the cut edges together, the loop leaves that tissue at its
// own length; tied tighter, the cut faces meet (tissue contact, collide/tissue_contact.h) and
// the loop squeezes what it holds. For each hole h of the stitch, its bite is the distance
// from the hole to its end's cut lip at the hole's angle on the hole's own hull
// (collide/end_gap.h, cutRingLip; the angle read from the hole's rest position), at rest b_h
// and now l_h; the stitch's compression is
//   c = 1 − Σ l_h / Σ b_h
// over its holes, 0 at the tissue's own length, > 0 squeezed, < 0 stretched. A stitch is the
// thread's crossing from one end to the other (two pierces next to each other along the
// thread, SutureState::pierces in chain order, on different ends of the severed vessel, with
// unbroken thread between them) with the other hole of each end's passage where the thread's
// next pierce outward is on the same end: two to four holes. A hole through the cut face
// itself (no bite) counts nothing.
//   Limit: c > `overTightCompression` = 0.25. The wall is nearly incompressible (Carew,
//   Vaishnav and Patel, "Compressibility of the arterial wall", Circ Res 23 (1968) 61–68), so
//   a bite shortened by a quarter bulges by 15 % in thickness and breadth (1/√0.75): the
//   puckered, blanched tissue inside the loop by which an examiner sees a stitch tied to
//   strangle rather than to appose ("approximate, do not strangulate"). Apposition itself
//   should squeeze far less: the cut faces stop at the contact's 10 µm and a snug knot's pull
//   spreads over bites of 0.2–0.3 mm. Measured once: a throw snugged over lesson 2b's stay
//   stitch until the walls were 0.05 mm apart squeezes its bites by 0.006
//   (StayStitchThrow.AThrowSnugged…); the shipped stitch, drawn through and not tied: 0.000.
//
// Thread in the lumen. Each thread node (the swage to the tail; the needle is not thread)
// inside an end of the vessel, behind its cut ring and ahead of its clamped ring along its
// axis, lies inside the lumen by its depth: with q the nearest point of that end's inner
// surface now and n that face's unit normal (into the lumen, mesh/vessel.h),
//   depth = n·(p − q),
// > 0 inside the lumen, < 0 in or beyond the wall. Left out are the thread's nodes where it
// belongs: a stitch's crossing between its two inner holes (pierces next to each other along
// the thread on different ends, neither on the outer surface), and a passage's track through
// the wall (next to each other on one end, not both on the inner surface: two inner holes of
// one end are a crossing of its lumen, a back-wall catch, and count). A link is longer than
// the wall is thick (0.15 against 0.1 mm in the shipped scenes), so the chain's nodes between
// a passage's holes need not lie in the wall the needle's track crosses: in the shipped
// stitch the node between end 1's holes lies 54 µm inside the lumen. Each run of neighbouring
// thread nodes deeper than the margin is one finding (a loop, a cut end) at its deepest node.
//   Limit: depth > `lumenMarginWalls` = 0.5 wall thicknesses (50 µm in a 0.1 mm wall). A
//   thread lying on the intima stands off it by its own radius (10-0 nylon: 11 µm) and the
//   contact's thickness (10 µm), and the faceted inner hull lies up to r_i(1 − cos(π/P))
//   inside the circle through its nodes (8 µm for P = 16): 29 µm in all. Deeper than half a
//   wall, nearly twice that, the thread stands out into the bloodstream where it gathers
//   platelets, not on the intima.
//
// Large edge overlap. Around the line every `sampleDeg`, each end's cut lip at that angle,
// the mid-wall point between its outer and inner hull's (cutRingLip); with a end 0's unit
// axis, ρ the distance from end 0's axis line (at rest),
//   apart  s = (lip₁ − lip₀)·a    (end 1 lies ahead of end 0 along a; < 0: past each other)
//   offset δ = |ρ₁ − ρ₀|
// The edges overlap where s < 0: they can only pass each other by one riding over the other.
// Each run of neighbouring samples with s < 0 and δ above the limit is one finding, at its
// largest offset.
//   Limit: δ > `overlapOffsetWalls` = 0.5 wall thicknesses. Edges meeting face to face have δ
//   near 0 whatever their gap; past each other with more than half the wall's thickness
//   between their mid-walls, each cut face meets the other end's intima or adventitia over
//   more than half its depth instead of its own layer: the intima no longer meets intima, the
//   condition for a patent anastomosis that end-to-end technique is built on.
//
// Angles follow assessment's scoring/attempt.h: degrees about end 0's axis (clamp → cut), 0°
// toward the microscope (circumference_frame.h), right-handed, [0, 360).
//
// Units: mm, degrees; compression dimensionless.

#include "microsim/sim/mesh/spring_model.h"
#include "microsim/sim/suture/suture_model.h"

#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace microsim::sim {

class Scene;
struct SceneDef;

struct EndStateParams {
  double overTightCompression = 0.25;  ///< compression c beyond which a stitch is over-tight (1)
  double lumenMarginWalls = 0.5;  ///< wall thicknesses of depth beyond which thread is in the lumen
  double overlapOffsetWalls =
      0.5;                 ///< wall thicknesses of radial offset beyond which edges overlap
  double sampleDeg = 2.0;  ///< degrees between samples of the suture line, > 0
  /// unit, normal to end 0's axis: 0° of the angles; none = toward the scene's camera eye
  std::optional<Vec3> angleZero;
};

enum class EndStateStatus : std::uint8_t {
  Checked,          ///< the numbers below hold
  NoSeveredVessel,  ///< the scene has no end 0 and end 1 of a severed vessel: nothing to check
};

enum class EndStateKind : std::uint8_t { OverTightStitch, ThreadInLumen, LargeEdgeOverlap };

/// One lapse: where, how much, and the limit it is beyond.
struct EndStateFinding {
  EndStateKind kind = EndStateKind::OverTightStitch;
  double angleDeg = std::numeric_limits<double>::quiet_NaN();  ///< [0, 360)
  /// compression c (1), depth in the lumen (mm) or radial offset (mm), by kind
  double measured = std::numeric_limits<double>::quiet_NaN();
  double limit = std::numeric_limits<double>::quiet_NaN();  ///< in the same unit
};

/// One stitch's loop as measured, over-tight or not.
struct StitchCompression {
  int crossing = -1;  ///< index into SutureState::pierces of the crossing's first hole
  int holes = 0;      ///< holes measured, 2–4
  double angleDeg = std::numeric_limits<double>::quiet_NaN();  ///< the holes' mean, [0, 360)
  double restMm = 0.0;                                         ///< Σ b_h
  double nowMm = 0.0;                                          ///< Σ l_h
  double compression = 0.0;                                    ///< 1 − nowMm / restMm
};

struct EndStateResult {
  EndStateStatus status = EndStateStatus::Checked;
  std::vector<StitchCompression> stitches;  ///< every stitch, in thread order
  /// mm: the deepest thread node in the lumen outside the crossings; NaN with no thread node
  /// inside either end
  double deepestThreadMm = std::numeric_limits<double>::quiet_NaN();
  /// mm: the largest radial offset δ where the edges are past each other; 0 where they never are
  double largestOverlapOffsetMm = 0.0;
  double lumenMarginMm = std::numeric_limits<double>::quiet_NaN();  ///< the limits in mm
  double overlapOffsetLimitMm = std::numeric_limits<double>::quiet_NaN();
  /// the lapses: over-tight stitches in thread order, thread in the lumen along the thread,
  /// overlaps by angle
  std::vector<EndStateFinding> findings;
};

/// Checks the severed vessel of `def` at tissue positions x (3 by #N, mm) with the scene's
/// thread `thread` (null: no thread; its needle's node count from def.needle).
EndStateResult checkEndState(const SceneDef& def, const Points& x,
                             const suture::SutureState* thread, const EndStateParams& params = {});

/// checkEndState on the scene as it is.
EndStateResult checkEndState(const Scene& scene, const EndStateParams& params = {});

}  // namespace microsim::sim
