#pragma once
// The finished anastomosis judged (DESIGN.md §Assessment; issue #19): every error of the
// Anastomosis Lapse Index (ALI; Ghanem et al., "Anastomosis Lapse Index (ALI): a validated
// end product assessment tool for simulation microsurgery training", J Reconstr Microsurg
// 2016) that the attempt shows, each with where it is. The ALI counts ten kinds of lapse;
// the index is their number.
//
// What an Attempt lets us judge, and how (the limits are EndProductLimits):
//   suture-line disruption  a SutureBreak event (the thread is gone: not located); a
//                           SuturePulledOut event (located at the pierce the thread slid out
//                           of); a leak, once the lumen's pressure test passes one in
//                           (LeakFinding, attempt.h: located at its largest gap, measured
//                           in mm against its limit).
//   back-wall stitch        a passage entering the back wall (pierce_metrics.h: catching it
//                           closes the lumen).
//   oblique stitch          the two passages of a stitch more than `obliqueDeg` apart around
//                           the circumference: the stitch is not parallel to the axis.
//   wide bite               a passage's bite above `wideBiteWalls` wall thicknesses.
//   partial-thickness bite  a passage with an exit that does not go through the whole wall.
//   unequal spacing         with ≥ 3 stitches on a vessel: a gap between neighbouring
//                           stitches (sorted around the circle, the last to the first) that
//                           differs from the mean gap (360° / stitches) by more than
//                           `unequalSpacingFraction` of it. Reported at the gap's middle, with
//                           the stitch the gap starts from (going up in angle).
//   wall tear               each TissueTear event. The event names only a tissue link, and
//                           an Attempt has no mesh to place it on: not located (angle NaN).
//   over-tight stitch       the final scene (Attempt::endState, sim/scene/end_state_check.h):
//                           a stitch's loop squeezing the bites it holds, their length now
//                           against at rest, compression beyond a quarter (1); located at
//                           the stitch's holes' mean angle.
//   thread in the lumen     the final scene: thread (a loop, a cut end) inside an end's inner
//                           surface deeper than half a wall (mm), other than a stitch's
//                           crossing between its inner holes and a passage's track through
//                           the wall; located at its deepest node.
//   large edge overlap      the final scene: the cut edges past each other with their
//                           mid-walls radially offset by more than half a wall (mm); located
//                           at the largest offset of each stretch of the line where they are.
//                           The check's limits are its own (EndStateParams), given with
//                           each error.
// Without a final scene (an attempt captured live, or built in a test) these three are not
// judged.
//
// A passage whose hole the thread never reached (PierceReleased: the needle was drawn back or
// moved off) is not in the finished anastomosis: needle trauma, not a bite. Its passage, and
// a stitch it is part of, are not judged.
//
// Angles follow attempt.h: degrees about the vessel axis, 0° toward the microscope, [0, 360).
// The engine reports kinds and numbers; naming them in words is the app's business.
//
// Units: millimetres, degrees, wall thicknesses.

#include "microsim/assessment/scoring/attempt.h"
#include "microsim/assessment/scoring/pierce_metrics.h"
#include "microsim/assessment/scoring/stitch_metrics.h"

#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace microsim::assessment {

/// The ALI's ten kinds of lapse, in the order of its list.
enum class EndProductErrorKind : std::uint8_t {
  SutureLineDisruption,
  BackWallStitch,
  ObliqueStitch,
  WideBite,
  PartialThicknessBite,
  UnequalSpacing,
  WallTear,
  OverTightStitch,   ///< from the final scene (Attempt::endState)
  ThreadInLumen,     ///< from the final scene
  LargeEdgeOverlap,  ///< from the final scene
};

/// The kinds, in enum order.
std::span<const EndProductErrorKind> endProductErrorKinds();
/// A stable key for files and programs: "suture_line_disruption", "back_wall_stitch", ...
std::string_view endProductErrorKey(EndProductErrorKind kind);
/// The kind whose endProductErrorKey is `key`; nullopt for a key no kind has.
std::optional<EndProductErrorKind> endProductErrorKindFromKey(std::string_view key);
/// The unit of an error's `measured` and `limit`: "mm", "deg", "walls", "1", "count", or ""
/// for a kind that is a plain yes (both NaN).
std::string_view endProductErrorUnit(EndProductErrorKind kind);

/// Where the limits come from. Each is the boundary of what counts as an error (strictly
/// beyond it is one).
struct EndProductLimits {
  /// wall thicknesses: the top of the 2–3 wall thicknesses that microsurgical teaching gives
  /// as the bite (DESIGN.md); a longer bite folds more wall into the line and puckers it
  double wideBiteWalls = 3.0;
  /// degrees between a stitch's two passages around the circumference: a 1 mm artery takes
  /// 7–8 stitches about 45–51° apart; a stitch skewed by a third of that spacing pulls its
  /// edges out of register against their neighbours, which an examiner sees as oblique
  double obliqueDeg = 15.0;
  /// fraction of the mean gap: a gap half as wide again as the mean (or half as narrow) is
  /// where the line leaks first (too wide) or crowds the wall (too narrow); smaller
  /// differences are within what careful hands leave
  double unequalSpacingFraction = 0.5;
};

struct EndProductError {
  EndProductErrorKind kind = EndProductErrorKind::SutureLineDisruption;
  int stitch = -1;   ///< index into stitchMetrics(pierceMetrics(attempt)); -1 if none
  int passage = -1;  ///< index into pierceMetrics(attempt); -1 if none
  int event = -1;    ///< index into Attempt::events for an error an event reports; -1 if none
  double angleDeg = std::numeric_limits<double>::quiet_NaN();  ///< where; NaN if not located
  double measured = std::numeric_limits<double>::quiet_NaN();  ///< in the kind's unit
  double limit = std::numeric_limits<double>::quiet_NaN();     ///< the limit it is beyond
};

/// Every error the attempt's end product shows: passages in order (back wall, partial
/// thickness, wide bite), then stitches (oblique), the spacing, then the events in order
/// (tears, breaks, pull-outs), then the final scene's (Attempt::endState: over-tight stitches,
/// thread in the lumen, edge overlaps, as the check lists them), then the leak.
std::vector<EndProductError> endProductErrors(const Attempt& attempt,
                                              const std::optional<LeakFinding>& leak = std::nullopt,
                                              const EndProductLimits& limits = {});

/// How many errors of `kind` the list holds.
int countEndProductErrors(const std::vector<EndProductError>& errors, EndProductErrorKind kind);

}  // namespace microsim::assessment
