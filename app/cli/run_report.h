#pragma once
// What `microsim-cli run` reports once a scene has run: the final state hash, every event
// (pierces with their angle and bite, knots with their type, throws and tension) and each stage's step times (median, p99, max), as a
// table for people and as JSON for programs.
#include "cli/cli.h"

#include "microsim/sim/scene/scene.h"

#include <array>
#include <string>
#include <vector>

namespace microsim::cli {

/// Every step's time per stage (s), in step order.
class StepTimeLog {
 public:
  static constexpr int kStages = 5;  ///< collision, tissue, suture, interactions, total

  void add(const sim::StageTimes& times);
  const std::vector<double>& stage(int s) const { return seconds_[static_cast<std::size_t>(s)]; }

 private:
  std::array<std::vector<double>, kStages> seconds_;
};

/// The table: scene, steps, hash, events, step times.
void printRunReport(QTextStream& out, const sim::Scene& scene, const QString& sceneFile,
                    const StepTimeLog& times);

/// The same as a JSON document: scene, steps, dt, hash, events (a pierce with its point,
/// face, angle, bite, ...; a knot event with its type, throws, tension and, as the kind has
/// them, the throw's handedness and wraps or the slip's cause and slide) and timings_ms per stage.
std::string runReportJson(const sim::Scene& scene, const QString& sceneFile,
                          const StepTimeLog& times);

}  // namespace microsim::cli
