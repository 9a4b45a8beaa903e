#pragma once
// What `microsim-cli score` reports: the score and pass, every metric with its value, target,
// weight, points and feedback key, the pierces and the stitches, and the finished
// anastomosis's errors (end_product.h) and its leak test (sim/scene/leak_test.h), as a table
// for people and as JSON for programs.
#include "cli/cli.h"

#include "microsim/assessment/scoring/rubric.h"
#include "microsim/assessment/scoring/score.h"

#include <nlohmann/json.hpp>

namespace microsim::cli {

/// What was scored: the scene replayed, the recording and how many frames it held.
struct ScoredFiles {
  QString scene;
  QString recording;
  int frames = 0;
};

void printScoreReport(QTextStream& out, const assessment::AttemptScore& score,
                      const assessment::Rubric& rubric, const ScoredFiles& files);

/// The same as JSON: score, passed, rubric, scene, recording, frames, truncated,
/// never_events, metrics, pierces, stitches, end_product, leak (a missing value is null; an
/// end-product error's "kind" is endProductErrorKey's, its "stitch" and "pierce" 0-based
/// indices into "stitches" and "pierces"; "leak" is the leak test: status, leaks,
/// largest_gap_mm, angle_deg, limit_mm, pressure_mmhg, or null without one).
nlohmann::json scoreReportJson(const assessment::AttemptScore& score,
                               const assessment::Rubric& rubric, const ScoredFiles& files);

}  // namespace microsim::cli
