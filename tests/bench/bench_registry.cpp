#include "bench_report.h"
#include "collision_bench.h"
#include "scene_bench.h"
#include "soak_bench.h"
#include "suture_bench.h"
#include "tissue_benches.h"

namespace microsim::bench {

// Each benchmark lives in its own file and is listed here once.
const std::vector<BenchEntry>& benchRegistry() {
  static const std::vector<BenchEntry> entries = {
      {"table1", "qss iterations per 1/30 s with and without cutout (paper Table 1)", runTable1},
      {"fig5", "qss max/mean error vs box size and vs iterations (paper Fig. 5)", runFig5},
      {"speed-error", "time to 10/1/0.1 % error for every tissue solver, warm and cold", runSpeedError},
      {"suture",
       "suture step time and max stretch vs links (50-2000), ftl (paper) vs direct; knot "
       "recognition and a knot drawn taut",
       runSuture},
      {"collision", "sphere/AABB trees: build, maintenance, query vs distance, against FCL", runCollision},
      {"scene", "scene step time by stage (median, p99) over one full stitch", runScene},
      {"soak", "30 simulated minutes of the default scene: memory and step time along it", runSoak},
  };
  return entries;
}

}  // namespace microsim::bench
