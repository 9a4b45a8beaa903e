#pragma once
// `microsim-cli bench collision`: the paper's sphere-tree evaluation (§5.4) beside FCL.

#include "bench_report.h"

namespace microsim::bench {

/// Build per triangle, MAINTENANCE per deformed triangle on the 100 by 100 grid (local and
/// scattered bumps), query time against distance for the 8 by 8 plane (8192 triangles)
/// against the ball of diameter 2 (1024 triangles) before and after deformation, and
/// refit + query; every figure for the sphere tree, the AABB tree and FCL (BVHModel refit).
BenchReport runCollision(const BenchOptions& options);

}  // namespace microsim::bench
