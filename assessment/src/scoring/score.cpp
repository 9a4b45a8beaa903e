#include "microsim/assessment/scoring/score.h"

#include <algorithm>
#include <cmath>

namespace microsim::assessment {

MetricScore scoreMetric(const RubricMetric& metric, double value, std::string unit) {
  MetricScore s;
  s.key = metric.key;
  s.value = value;
  s.unit = std::move(unit);
  s.target = metric.target;
  s.tolerance = metric.tolerance;
  s.weight = metric.weight;
  if (!std::isfinite(value)) {
    s.feedback = metric.key + ".missing";
    return s;
  }

  // how far past the target on the bad side
  const double over = value - metric.target;
  double d = 0.0;
  switch (metric.bad) {
    case BadSide::Above: d = std::max(0.0, over); break;
    case BadSide::Below: d = std::max(0.0, -over); break;
    case BadSide::Both: d = std::abs(over); break;
  }
  if (d <= metric.tolerance) {
    s.points = 1.0;
    return s;
  }
  s.points = d >= metric.limit
                 ? 0.0
                 : 1.0 - (d - metric.tolerance) / (metric.limit - metric.tolerance);
  s.feedback = over > 0.0 ? metric.feedbackAbove : metric.feedbackBelow;
  return s;
}

AttemptScore scoreMetrics(const std::vector<MetricValue>& values, const Rubric& rubric) {
  AttemptScore out;
  out.rubricId = rubric.id;
  out.rubricVersion = rubric.version;
  const auto find = [&](const std::string& key) -> const MetricValue* {
    for (const MetricValue& v : values)
      if (v.key == key) return &v;
    return nullptr;
  };

  // each metric's points
  for (const RubricMetric& m : rubric.metrics) {
    const MetricValue* v = find(m.key);
    MetricScore s = v ? scoreMetric(m, v->value, v->unit)
                      : scoreMetric(m, std::nan(""), std::string());
    if (v && !v->applicable) {
      s.applicable = false;
      s.weight = 0.0;
      s.feedback = m.key + ".not_applicable";
    }
    out.metrics.push_back(std::move(s));
  }

  // how the task was done counts once some of it was done (rubric.h, only_if_task_done)
  bool hasTask = false;
  bool taskDone = false;
  for (std::size_t i = 0; i < rubric.metrics.size(); ++i) {
    if (rubric.metrics[i].onlyIfTaskDone || !out.metrics[i].applicable) continue;
    hasTask = true;
    taskDone = taskDone || out.metrics[i].points > 0.0;
  }
  if (hasTask && !taskDone)
    for (std::size_t i = 0; i < rubric.metrics.size(); ++i) {
      MetricScore& s = out.metrics[i];
      if (!rubric.metrics[i].onlyIfTaskDone || !s.applicable) continue;
      s.points = 0.0;
      s.feedback = "task.not_done";
    }

  // weighted points
  double weighted = 0.0;
  double weights = 0.0;
  for (const MetricScore& s : out.metrics) {
    weighted += s.weight * s.points;
    weights += s.weight;
  }
  out.score = weights > 0.0 ? 100.0 * weighted / weights : 0.0;

  // never-events cap it
  for (const NeverEvent& e : rubric.neverEvents) {
    const MetricValue* v = find(e.metric);
    if (!v || !std::isfinite(v->value) || !(v->value > e.above)) continue;
    out.neverEvents.push_back(e.feedback);
    out.score = std::min(out.score, e.cap);
  }
  out.passed = out.score >= rubric.passMark;
  return out;
}

AttemptScore scoreAttempt(const Attempt& attempt, const Rubric& rubric) {
  AttemptMetrics metrics = computeMetrics(attempt, rubric.motion);
  AttemptScore out = scoreMetrics(metrics.values, rubric);
  out.pierces = std::move(metrics.pierces);
  out.stitches = std::move(metrics.stitches);
  out.endProduct = std::move(metrics.endProduct);
  out.leak = attempt.leak;
  out.truncated = attempt.truncated;
  return out;
}

bool proficient(const std::vector<double>& testScoresOldestFirst, const Rubric& rubric) {
  for (std::size_t i = 1; i < testScoresOldestFirst.size(); ++i)
    if (testScoresOldestFirst[i - 1] >= rubric.passMark &&
        testScoresOldestFirst[i] >= rubric.passMark)
      return true;
  return false;
}

}  // namespace microsim::assessment
