#pragma once
// Scoring: a rubric (rubric.h) applied to an attempt's metrics (metrics.h).
//
//   score = 100 · Σ weight·points / Σ weight, then capped by every never-event that fired;
//   a metric that does not apply to the attempt (MetricValue::applicable false) is left out
//   of both sums, so its weight is spread over the others in proportion; its MetricScore
//   has weight 0 and feedback "<key>.not_applicable". A metric marked only_if_task_done
//   (rubric.h) scores 0 points, feedback "task.not_done", unless some applicable metric
//   without the mark earned points (when the rubric has such metrics).
//   passed = score ≥ pass_mark.
// Proficiency is the pass mark on two consecutive Test attempts.

#include "microsim/assessment/scoring/attempt.h"
#include "microsim/assessment/scoring/end_product.h"
#include "microsim/assessment/scoring/metrics.h"
#include "microsim/assessment/scoring/pierce_metrics.h"
#include "microsim/assessment/scoring/rubric.h"
#include "microsim/assessment/scoring/stitch_metrics.h"

#include <optional>
#include <string>
#include <vector>

namespace microsim::assessment {

struct MetricScore {
  std::string key;
  double value = 0.0;      ///< in `unit`; NaN when the attempt lacks it
  std::string unit;
  double target = 0.0;
  double tolerance = 0.0;
  double weight = 0.0;
  double points = 0.0;     ///< 0..1
  std::string feedback;    ///< empty when full points, else a key like "entry_angle.too_oblique"
  bool applicable = true;  ///< false: weighted out (weight 0), feedback "<key>.not_applicable"
};

struct AttemptScore {
  double score = 0.0;      ///< 0..100
  bool passed = false;
  std::string rubricId;
  int rubricVersion = 0;
  std::vector<MetricScore> metrics;       ///< rubric order
  std::vector<std::string> neverEvents;   ///< feedback keys of the never-events that fired
  std::vector<PierceMetrics> pierces;
  std::vector<StitchMetrics> stitches;
  std::vector<EndProductError> endProduct;  ///< the finished anastomosis's errors (end_product.h)
  std::optional<LeakFinding> leak;          ///< the attempt's leak test, when it had one
  bool truncated = false;                 ///< scored from a partial recording
};

/// Points (0..1) and feedback of one value against one rubric metric.
MetricScore scoreMetric(const RubricMetric& metric, double value, std::string unit);

/// Scores a metric set (no pierce lists).
AttemptScore scoreMetrics(const std::vector<MetricValue>& values, const Rubric& rubric);

/// Computes the metrics with the rubric's motion parameters and scores them.
AttemptScore scoreAttempt(const Attempt& attempt, const Rubric& rubric);

/// True when two consecutive scores (Test attempts, oldest first) reach the pass mark.
bool proficient(const std::vector<double>& testScoresOldestFirst, const Rubric& rubric);

}  // namespace microsim::assessment
