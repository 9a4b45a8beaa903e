#pragma once
// A rubric turns an attempt's metrics (metrics.h) into a 0–100 score with feedback keys.
// Rubrics are versioned JSON files, resources/rubrics/<lesson>.json, schema
// resources/schema/rubric.schema.json:
//
//   {"id": "03_single_stitch",                   required, the lesson it grades
//    "version": 1,                                required, ≥ 1; stored with every score
//    "pass_mark": 70,                             required, 0..100
//    "motion": {"movement_speed", "idle_speed", "min_movement_s", "merge_gap_s"},  optional
//    "metrics": [                                 required, at least one
//      {"key": "entry_angle",                     a metrics.h key
//       "weight": 2,                              > 0
//       "target": 0,                              the ideal value
//       "tolerance": 15,                          full points within this of the target
//       "limit": 45,                              no points from this far (> tolerance)
//       "bad": "above" | "below" | "both",        which side of the target loses points
//       "feedback": {"above": "entry_angle.too_oblique", "below": ...},   optional keys
//       "only_if_task_done": true},               optional (false): see below
//      ...],
//    "never_events": [                            optional
//      {"metric": "back_wall_catches", "above": 0, "cap": 0,
//       "feedback": "never.back_wall_catch"}]}
//
// Points of a metric (0..1): d = how far the value is past the target on the bad side
// (|v − t| for "both"); 1 when d ≤ tolerance, 0 when d ≥ limit, linear between. A NaN
// value (the attempt lacks it) scores 0 with feedback "<key>.missing"; a metric that does not
// apply to the attempt's input (MetricValue::applicable) is weighted out instead (score.h,
// feedback "<key>.not_applicable"). Default feedback
// keys are "<key>.too_high" and "<key>.too_low". A never-event fires when its metric's
// value exceeds "above"; it caps the score at "cap" (0 zeroes it).
//
// "only_if_task_done" marks a metric that grades how the task was done rather than whether:
// time, economy of motion, regrasps, the finished repair's lapses. Such a metric earns its
// points only when a metric without the mark (the task: stitches, knots, pierces) earned
// some; otherwise it scores 0 with feedback "task.not_done". An attempt in which nothing was
// done no longer collects points for being quick and still (score.h).
//
// Loading never throws: errors name the file, line:column and field path like the scene
// loader ("metrics[2].tolerance"). Unknown keys and unknown metric names are errors.

#include "microsim/assessment/scoring/motion_metrics.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace microsim::assessment {

enum class BadSide : std::uint8_t { Above, Below, Both };

struct RubricMetric {
  std::string key;
  double weight = 1.0;
  double target = 0.0;     ///< in the metric's unit
  double tolerance = 0.0;  ///< deviation with full points (metric's unit)
  double limit = 1.0;      ///< deviation with no points (metric's unit), > tolerance
  BadSide bad = BadSide::Both;
  std::string feedbackAbove;  ///< key when too high
  std::string feedbackBelow;  ///< key when too low
  bool onlyIfTaskDone = false;  ///< points only once a task metric earned some (see above)
};

struct NeverEvent {
  std::string metric;
  double above = 0.0;    ///< fires when the metric's value is > this
  double cap = 0.0;      ///< the score's ceiling when it fires (0..100)
  std::string feedback;  ///< key, e.g. "never.back_wall_catch"
};

struct Rubric {
  std::string id;
  int version = 1;
  double passMark = 70.0;  ///< 0..100
  MotionParams motion;
  std::vector<RubricMetric> metrics;
  std::vector<NeverEvent> neverEvents;
  std::string file;  ///< as loaded, empty when parsed from memory
};

enum class RubricErrorKind : std::uint8_t {
  FileNotFound,
  MalformedJson,  ///< not JSON; line/column point at the parse failure
  WrongType,      ///< a field has the wrong JSON type
  MissingField,
  UnknownField,
  UnknownMetric,  ///< "key"/"metric" names no metrics.h metric
  InvalidValue,   ///< out of range (weight ≤ 0, limit ≤ tolerance, pass_mark > 100, ...)
};

struct RubricError {
  RubricErrorKind kind = RubricErrorKind::MalformedJson;
  std::string file;
  int line = 0;    ///< 1-based; 0 when unknown
  int column = 0;  ///< 1-based, bytes
  std::string field;  ///< JSON path, e.g. "metrics[2].tolerance"; empty for the root
};

std::variant<Rubric, RubricError> loadRubric(const std::string& path);
std::variant<Rubric, RubricError> parseRubric(std::string_view text,
                                              const std::string& file = {});

}  // namespace microsim::assessment
