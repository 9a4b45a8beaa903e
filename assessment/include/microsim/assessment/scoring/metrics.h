#pragma once
// The attempt's metrics by key: what a rubric can weigh. Every metric is one number; a
// metric the attempt cannot have (an entry angle without a pierce) is NaN. A metric that
// does not apply to how the attempt was made is NaN and not applicable: smoothness and
// idle time of stepped input (keyboard; motion_metrics.h), which score.h weights out.
//
//   key                  unit   meaning
//   time                 s      duration of the attempt
//   path_length          mm     both hands' tool-tip path
//   path_length_left     mm     left hand's (motion_metrics.h)
//   path_length_right    mm     right hand's
//   movements            count  velocity-threshold movements of both hands
//   smoothness           1      mean log dimensionless jerk of those movements (≤ 0; higher
//                               is smoother)
//   idle_time            s      both hands below the idle speed
//   regrasps             count  grabs after a release by the same hand
//   suture_breaks        count  SutureBreak events
//   max_stretch          1      largest link strain (l − r)/r of the tissue
//   tissue_damage        count  TissueOverStretch and TissueTear events
//   passages             count  wall passages (pierce_metrics.h)
//   arc_deviation        mm     largest distance of the needle tip from its own arc between
//                               pierces of one hold (arc_metrics.h)
//   entry_angle          deg    mean entry angle to the wall normal
//   exit_angle           deg    mean exit angle (passages with an exit)
//   bite                 mm     mean bite from the cut edge
//   bite_walls           1      mean bite in wall thicknesses
//   full_thickness       1      fraction of passages through the whole wall
//   back_wall_catches    count  passages entering the back wall
//   stitches             count  stitches (stitch_metrics.h)
//   bite_symmetry        mm     mean |bite_a − bite_b| of the stitches
//   spacing              deg    mean angle between consecutive stitches
//   triangulation_error  deg    largest |arc − 120°| of the first three stitches
//   lapse_index          count  errors of the finished anastomosis (end_product.h; with the
//                               final scene's over-tight stitches, thread in the lumen and edge
//                               overlaps when the attempt carries them, Attempt::endState;
//                               without the leak test, Attempt::leak, which the score report
//                               shows beside)
//   oblique_stitches     count  of them, stitches not parallel to the axis
//   partial_thickness_bites
//                        count  passages not through the whole wall
//   wide_bites           count  bites beyond the wide-bite limit
//   unequal_spacing      count  gaps between neighbouring stitches off the mean
//   knots_tied           count  knots pulled tight (knot_metrics.h)
//   secure_knots         count  of them, square or surgeon's knots that did not slip
//   knots_slipped        count  KnotSlipped events
//   knot_throws          count  mean throws of the knots pulled tight (NaN without one)
//   thread_cuts          count  cuts that left a cut end on a stitch
//   cut_end_length       mm     mean cut-end length of those cuts (NaN without one)
//   leaks                count  1 when the leak test on the final scene finds the suture line
//                               open, 0 when it holds; NaN without a verdict (no test run: an
//                               attempt not replayed; or not solved). Not in lapse_index: a
//                               line of fewer stitches than a closed ring always leaks, which
//                               lessons 3 and 4 ask for
//   leak_gap             mm     the leak test's largest gap along the suture line

#include "microsim/assessment/scoring/arc_metrics.h"
#include "microsim/assessment/scoring/attempt.h"
#include "microsim/assessment/scoring/end_product.h"
#include "microsim/assessment/scoring/knot_metrics.h"
#include "microsim/assessment/scoring/motion_metrics.h"
#include "microsim/assessment/scoring/pierce_metrics.h"
#include "microsim/assessment/scoring/stitch_metrics.h"

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace microsim::assessment {

struct MetricInfo {
  std::string_view key;
  std::string_view unit;  ///< "s", "mm", "deg", "count", "1"
};

/// Every metric key computeMetrics produces, in table order.
std::span<const MetricInfo> metricCatalogue();
/// The catalogue entry of `key`, or null.
const MetricInfo* findMetric(std::string_view key);

struct MetricValue {
  std::string key;
  double value = 0.0;  ///< NaN when the attempt cannot have it
  std::string unit;
  bool applicable = true;  ///< false: the metric does not apply to this attempt's input
};

struct AttemptMetrics {
  std::vector<MetricValue> values;  ///< catalogue order
  std::vector<PierceMetrics> pierces;
  std::vector<StitchMetrics> stitches;
  std::vector<EndProductError> endProduct;  ///< with default limits, without a leak test
  std::array<HandMotion, sim::kHandCount> hands;

  /// The value of `key`; nullopt for an unknown key.
  std::optional<double> value(std::string_view key) const;
};

AttemptMetrics computeMetrics(const Attempt& attempt, const MotionParams& params = {});

}  // namespace microsim::assessment
