#include "collision_bench.h"

#include "collision_fcl.h"
#include "collision_shapes.h"

#include "microsim/sim/collide/sphere_tree.h"
#include "microsim/sim/collide/tree_queries.h"
#include "microsim/sim/mesh/grid.h"

#include <algorithm>
#include <chrono>
#include <memory>
#include <optional>
#include <random>
#include <string>

namespace microsim::bench {

namespace {

using microsim::sim::SpringModel;
using microsim::sim::collide::AabbTree;
using microsim::sim::collide::FeaturePair;
using microsim::sim::collide::Points;
using microsim::sim::collide::SphereTree;
using Clock = std::chrono::steady_clock;

// the paper's figures (Pentium II 400 MHz), in the units of our rows
constexpr double kPaperBuildNsPerTriangle = 100e3;   // ~0.1 ms per triangle
constexpr double kPaperMaintainNsPerTriangle = 60e3;  // 0.06 ms per deformed triangle
constexpr double kPaperSlowestQueryUs = 60e3;         // just under 60 ms near contact

// seconds per call of f: the median of 5 batches, each long enough to time reliably
template <class F>
double secondsPerCall(F&& f, double batchSeconds) {
  // calibrate the batch size
  int calls = 1;
  for (;;) {
    const auto start = Clock::now();
    for (int i = 0; i < calls; ++i) f();
    const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    if (elapsed >= batchSeconds || calls >= (1 << 24)) break;
    calls *= elapsed > 0.0 ? std::clamp(static_cast<int>(batchSeconds / elapsed * 1.2), 2, 64) : 64;
  }
  std::vector<double> batches;
  for (int b = 0; b < 5; ++b) {
    const auto start = Clock::now();
    for (int i = 0; i < calls; ++i) f();
    batches.push_back(std::chrono::duration<double>(Clock::now() - start).count() / calls);
  }
  std::sort(batches.begin(), batches.end());
  return batches[2];
}

struct Sizes {
  int gridCells;      // the maintenance grid: gridCells² squares, 2 triangles each
  int planeCells;     // the query plane: planeCells² squares over 8 by 8 mm
  int ballSlices;     // the ball: 2 slices (bands − 1) triangles
  int ballBands;
  int localBumps;     // maintenances with one bump each
  int scatteredRounds;  // maintenances with several bumps each
  double batch;       // seconds per timing batch
};

Sizes sizesFor(const BenchOptions& o) {
  if (o.quick) return {30, 16, 16, 9, 10, 4, 2e-4};
  return {100, 64, 32, 17, 200, 50, 4e-3};
}

std::string gridName(int cells) {
  return std::to_string(cells) + "x" + std::to_string(cells) + " grid (" +
         std::to_string(2 * cells * cells) + " tris)";
}

BenchRow row(const std::string& caseName, const std::string& metric, double value,
             const std::string& unit, std::optional<double> paper = std::nullopt,
             std::optional<double> peer = std::nullopt) {
  BenchRow r{"collision", caseName, metric, value, unit, paper, peer, std::nullopt};
  if (peer && *peer > 0.0)
    r.ratio = value / *peer;
  else if (paper && *paper > 0.0)
    r.ratio = value / *paper;
  return r;
}

// ---- build --------------------------------------------------------------------------------

void benchBuild(const Sizes& s, BenchReport& report) {
  const SpringModel grid = sim::gridMesh(s.gridCells, s.gridCells, 1.0);
  const Points& x = grid.restPositions();
  const double tris = static_cast<double>(grid.triangles().size());
  const double sphere = secondsPerCall([&] { (void)SphereTree::overTriangles(grid.triangles(), x); }, s.batch);
  const double aabb = secondsPerCall([&] { (void)AabbTree::overTriangles(grid.triangles(), x); }, s.batch);
  std::optional<double> fcl;
  if (fclAvailable())
    fcl = 1e9 / tris * secondsPerCall([&] { FclMesh m(FclVolume::Obbrss, x, grid.triangles()); }, s.batch);
  report.rows.push_back(row(gridName(s.gridCells) + ", sphere tree", "build per triangle",
                            1e9 * sphere / tris, "ns", kPaperBuildNsPerTriangle, fcl));
  report.rows.push_back(row(gridName(s.gridCells) + ", AABB tree", "build per triangle",
                            1e9 * aabb / tris, "ns", std::nullopt, fcl));
}

// ---- maintenance --------------------------------------------------------------------------

struct MaintainResult {
  double nsPerTriangle = 0.0;
  double refitsPerTriangle = 0.0;
  double fclNsPerTriangle = 0.0;
};

// `bumpsPer` random bumps (radius 1–10, height ±1) before each maintenance
template <class Tree>
MaintainResult benchMaintain(const Sizes& s, int rounds, int bumpsPer, unsigned seed) {
  const SpringModel grid = sim::gridMesh(s.gridCells, s.gridCells, 1.0);
  Points x = grid.restPositions();
  Tree tree = Tree::overTriangles(grid.triangles(), x);
  std::unique_ptr<FclMesh> fcl;
  if (fclAvailable()) fcl = std::make_unique<FclMesh>(FclVolume::Obbrss, x, grid.triangles());

  // triangles of each vertex, to name the deformed ones
  std::vector<std::vector<int>> trianglesOf(x.cols());
  for (int t = 0; t < static_cast<int>(grid.triangles().size()); ++t)
    for (const int v : grid.triangles()[t]) trianglesOf[v].push_back(t);

  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> vertex(0, static_cast<int>(x.cols()) - 1);
  std::uniform_real_distribution<double> radius(1.0, 10.0);
  std::uniform_real_distribution<double> height(-1.0, 1.0);
  double seconds = 0.0, fclSeconds = 0.0, triangles = 0.0, refits = 0.0;
  std::vector<char> marked(grid.triangles().size(), 0);
  for (int r = 0; r < rounds; ++r) {
    // deform, and list the deformed triangles once each
    std::vector<int> deformed;
    for (int b = 0; b < bumpsPer; ++b)
      for (const int v : bump(x, vertex(rng), radius(rng), height(rng)))
        for (const int t : trianglesOf[v])
          if (!marked[t]) {
            marked[t] = 1;
            deformed.push_back(t);
          }
    for (const int t : deformed) marked[t] = 0;

    // maintain (repeating it redoes the same refits)
    refits += tree.maintain(deformed, x);
    seconds += secondsPerCall([&] { tree.maintain(deformed, x); }, s.batch / 4);
    if (fcl) fclSeconds += secondsPerCall([&] { fcl->update(x); }, s.batch / 4);
    triangles += static_cast<double>(deformed.size());
  }
  // per deformed triangle: total maintenance time over total deformed triangles
  return {1e9 * seconds / triangles, refits / triangles, 1e9 * fclSeconds / triangles};
}

void benchMaintenance(const Sizes& s, unsigned seed, BenchProgress& progress, BenchReport& report) {
  struct Case {
    std::string name;
    int rounds;
    int bumps;
  };
  const Case cases[] = {{"local (1 bump of r 1-10)", s.localBumps, 1},
                        {"scattered (8 bumps of r 1-10)", s.scatteredRounds, 8}};
  for (const Case& c : cases) {
    const std::string where = gridName(s.gridCells) + ", " + c.name;
    progress.next("maintenance, " + where);
    const MaintainResult sphere = benchMaintain<SphereTree>(s, c.rounds, c.bumps, seed);
    const MaintainResult aabb = benchMaintain<AabbTree>(s, c.rounds, c.bumps, seed);
    std::optional<double> fcl;
    if (fclAvailable()) fcl = sphere.fclNsPerTriangle;
    report.rows.push_back(row(where + ", sphere tree", "maintenance per deformed triangle",
                              sphere.nsPerTriangle, "ns", kPaperMaintainNsPerTriangle, fcl));
    report.rows.push_back(row(where + ", AABB tree", "maintenance per deformed triangle",
                              aabb.nsPerTriangle, "ns", std::nullopt, fcl));
    report.rows.push_back(row(where + ", sphere tree", "volumes refit per deformed triangle",
                              sphere.refitsPerTriangle, "count"));
  }
}

// ---- queries ------------------------------------------------------------------------------

// gap between the ball's lowest point and the plane (mm): 64 apart to 1 of penetration
std::vector<double> queryDistances(bool quick) {
  if (quick) return {64, 4, 1, 0.25, 0.05, 0, -0.5, -1};
  return {64, 32, 16, 8, 4, 2, 1, 0.5, 0.25, 0.125, 0.0625, 0.03, 0.01, 0.0, -0.125, -0.25, -0.5, -0.75, -1};
}

struct PathTimes {
  std::vector<double> first;  // µs per distance
  std::vector<double> all;    // µs per distance
  std::vector<double> refitAll;  // µs per distance: refit (maintenance + moving ball) and all pairs
  std::size_t deepestPairs = 0;  // colliding pairs at the deepest penetration
};

template <class Tree>
PathTimes ourPath(const Sizes& s, const Points& plane, Tree& planeTree,
                  const std::vector<int>& lastBump, const TriangleSoup& ball,
                  const std::vector<double>& distances) {
  PathTimes out;
  Points xBall = ball.x;
  Tree ballTree = Tree::overTriangles(ball.triangles, xBall);
  std::vector<FeaturePair> pairs;
  for (const double d : distances) {
    xBall = ball.x;
    xBall.row(2).array() += d + 1.0;
    ballTree.refitAll(xBall);
    out.first.push_back(1e6 * secondsPerCall([&] { (void)firstHit(planeTree, plane, ballTree, xBall); }, s.batch));
    out.all.push_back(1e6 * secondsPerCall([&] { allPairs(planeTree, plane, ballTree, xBall, pairs); }, s.batch));
    out.deepestPairs = pairs.size();
    out.refitAll.push_back(1e6 * secondsPerCall([&] {
      planeTree.maintain(lastBump, plane);
      ballTree.refitAll(xBall);
      allPairs(planeTree, plane, ballTree, xBall, pairs);
    }, s.batch));
  }
  return out;
}

PathTimes fclPath(const Sizes& s, const Points& plane, FclMesh& planeMesh, const TriangleSoup& ball,
                  const std::vector<double>& distances) {
  PathTimes out;
  FclMesh ballMesh(FclVolume::Obbrss, ball.x, ball.triangles);
  for (const double d : distances) {
    const Eigen::Vector3d offset(0.0, 0.0, d + 1.0);
    out.first.push_back(1e6 * secondsPerCall([&] { (void)planeMesh.collide(ballMesh, offset, true); }, s.batch));
    std::size_t n = 0;
    out.all.push_back(1e6 * secondsPerCall([&] { n = planeMesh.collide(ballMesh, offset, false); }, s.batch));
    out.deepestPairs = n;
    out.refitAll.push_back(1e6 * secondsPerCall([&] {
      planeMesh.update(plane);
      (void)planeMesh.collide(ballMesh, offset, false);
    }, s.batch));
  }
  return out;
}

double maxOf(const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); }
double sumOf(const std::vector<double>& v) {
  double total = 0.0;
  for (const double x : v) total += x;
  return total;
}

void benchQueries(const Sizes& s, unsigned seed, bool quick, BenchProgress& progress, BenchReport& report) {
  const SpringModel grid = sim::gridMesh(s.planeCells, s.planeCells, 8.0 / s.planeCells);
  const TriangleSoup ball = uvBall(s.ballSlices, s.ballBands, 1.0);
  const std::vector<double> distances = queryDistances(quick);
  const std::string pathName = "plane " + std::to_string(grid.triangles().size()) + " tris vs ball " +
                               std::to_string(ball.triangles.size()) + " tris";

  // before deformation
  progress.next("queries, " + pathName + ", undeformed");
  Points plane = grid.restPositions();
  SphereTree sphereTree = SphereTree::overTriangles(grid.triangles(), plane);
  AabbTree aabbTree = AabbTree::overTriangles(grid.triangles(), plane);
  const std::vector<int> noBump;
  const PathTimes sphereBefore = ourPath(s, plane, sphereTree, noBump, ball, distances);
  const PathTimes aabbBefore = ourPath(s, plane, aabbTree, noBump, ball, distances);
  std::unique_ptr<FclMesh> fclPlane;
  std::optional<PathTimes> fclBefore;
  if (fclAvailable()) {
    fclPlane = std::make_unique<FclMesh>(FclVolume::Obbrss, plane, grid.triangles());
    fclBefore = fclPath(s, plane, *fclPlane, ball, distances);
  }

  // large deformations: 20 bumps of radius 0.5–2 mm and height ±0.3 mm, then maintenance
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> vertex(0, static_cast<int>(plane.cols()) - 1);
  std::uniform_real_distribution<double> radius(0.5, 2.0);
  std::uniform_real_distribution<double> height(-0.3, 0.3);
  std::vector<int> lastBump;
  std::vector<std::vector<int>> trianglesOf(plane.cols());
  for (int t = 0; t < static_cast<int>(grid.triangles().size()); ++t)
    for (const int v : grid.triangles()[t]) trianglesOf[v].push_back(t);
  for (int b = 0; b < 20; ++b) {
    const std::vector<int> moved = bump(plane, vertex(rng), radius(rng), height(rng));
    sphereTree.maintainVertices(moved, plane);
    aabbTree.maintainVertices(moved, plane);
    lastBump.clear();
    for (const int v : moved) lastBump.insert(lastBump.end(), trianglesOf[v].begin(), trianglesOf[v].end());
  }
  progress.next("queries, " + pathName + ", deformed");
  const PathTimes sphereAfter = ourPath(s, plane, sphereTree, lastBump, ball, distances);
  const PathTimes aabbAfter = ourPath(s, plane, aabbTree, lastBump, ball, distances);
  std::optional<PathTimes> fclAfter;
  if (fclPlane) {
    fclPlane->update(plane);
    fclAfter = fclPath(s, plane, *fclPlane, ball, distances);
  }

  // rows: the slowest point of the path and the whole path
  const auto peerOf = [](const std::optional<PathTimes>& p, auto pick) -> std::optional<double> {
    if (!p) return std::nullopt;
    return pick(*p);
  };
  struct Tree {
    std::string name;
    const PathTimes* before;
    const PathTimes* after;
  };
  const Tree trees[] = {{"sphere tree", &sphereBefore, &sphereAfter}, {"AABB tree", &aabbBefore, &aabbAfter}};
  for (const Tree& t : trees) {
    for (const bool after : {false, true}) {
      const PathTimes& p = after ? *t.after : *t.before;
      const std::optional<PathTimes>& f = after ? fclAfter : fclBefore;
      const std::string where = pathName + (after ? ", deformed, " : ", undeformed, ") + t.name;
      report.rows.push_back(row(where, "slowest first-hit query on the path", maxOf(p.first), "us",
                                kPaperSlowestQueryUs,
                                peerOf(f, [](const PathTimes& q) { return maxOf(q.first); })));
      report.rows.push_back(row(where, "slowest all-pairs query on the path", maxOf(p.all), "us",
                                std::nullopt, peerOf(f, [](const PathTimes& q) { return maxOf(q.all); })));
      report.rows.push_back(row(where, "all-pairs queries over the whole path", sumOf(p.all), "us",
                                std::nullopt, peerOf(f, [](const PathTimes& q) { return sumOf(q.all); })));
      if (after)
        report.rows.push_back(row(where, "refit + all-pairs, slowest on the path", maxOf(p.refitAll), "us",
                                  std::nullopt,
                                  peerOf(f, [](const PathTimes& q) { return maxOf(q.refitAll); })));
    }
    report.rows.push_back(row(pathName + ", " + t.name, "colliding pairs at 1 mm penetration",
                              static_cast<double>(t.before->deepestPairs), "count", std::nullopt,
                              fclBefore ? std::optional<double>(static_cast<double>(fclBefore->deepestPairs))
                                        : std::nullopt));
  }

  // plots: query time against distance
  const auto curve = [&](const std::string& label, const std::vector<double>& y) {
    return BenchCurve{label, distances, y};
  };
  BenchPlot first{"First hit (COLLISION): " + pathName, "gap between ball and plane (mm; < 0: penetration)",
                  "query time (us)", false, true, {}};
  first.curves.push_back(curve("sphere tree", sphereBefore.first));
  first.curves.push_back(curve("sphere tree, deformed", sphereAfter.first));
  first.curves.push_back(curve("AABB tree", aabbBefore.first));
  first.curves.push_back(curve("AABB tree, deformed", aabbAfter.first));
  if (fclBefore) first.curves.push_back(curve("FCL OBBRSS", fclBefore->first));
  if (fclAfter) first.curves.push_back(curve("FCL OBBRSS, deformed", fclAfter->first));
  BenchPlot all{"All colliding pairs: " + pathName, "gap between ball and plane (mm; < 0: penetration)",
                "query time (us)", false, true, {}};
  all.curves.push_back(curve("sphere tree", sphereBefore.all));
  all.curves.push_back(curve("sphere tree, deformed", sphereAfter.all));
  all.curves.push_back(curve("AABB tree", aabbBefore.all));
  all.curves.push_back(curve("AABB tree, deformed", aabbAfter.all));
  if (fclBefore) all.curves.push_back(curve("FCL OBBRSS", fclBefore->all));
  if (fclAfter) all.curves.push_back(curve("FCL OBBRSS, deformed", fclAfter->all));
  report.plots.push_back(std::move(first));
  report.plots.push_back(std::move(all));
}

}  // namespace

BenchReport runCollision(const BenchOptions& options) {
  const Sizes s = sizesFor(options);
  BenchReport report;
  // build, two maintenance cases, queries before and after deformation
  BenchProgress progress(options.progress, 5);
  progress.next("build, " + gridName(s.gridCells));
  benchBuild(s, report);
  benchMaintenance(s, options.seed, progress, report);
  benchQueries(s, options.seed, options.quick, progress, report);
  return report;
}

}  // namespace microsim::bench
