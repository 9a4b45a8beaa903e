#pragma once
// The tissue's drawn surface made smooth: a coarse simulated mesh shown as finely as a mesh
// ten times denser, at the cost of a sparse product a frame (issue 17's "multi-resolution
// equivalent": the physics keeps the coarse nodes, the eye gets the fine surface).
//
// The surface is Loop's subdivision surface of the tissue's triangles (OpenSubdiv's Far
// refiner), refined `levels` times and every refined vertex moved to its limit position, so
// each is a fixed weighted sum of coarse control points. Those control points are not the
// nodes themselves: Loop's surface only approximates its control mesh (a 16-sided ring would
// shrink by 2.5 % of its radius), and the thread's holes, the jaws' contacts and the pierce
// marks all sit on the nodes. So the control points are solved for once a frame, so that the
// limit surface passes through every node (a sparse LU of the nodes' limit weights, factorised
// once: its rows are the limit masks, diagonally dominant, well conditioned).
//
// Edges whose faces meet at more than kCreaseAngleDeg at rest (a vessel's cut face against its
// walls, a box's edges) are infinitely sharp creases: they stay crisp lines instead of being
// rounded off, and the faces on either side stay smooth up to them.
//
// Built once per scene (0.01–0.1 s); `place` is a sparse LU solve and one sparse product, with no
// allocation once its outputs are sized. Units: those of the positions given.

#include "microsim/sim/mesh/spring_model.h"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace microsim::sim {

/// Faces meeting at more than this dihedral angle at rest are kept apart by a sharp crease.
inline constexpr double kCreaseAngleDeg = 50.0;

/// Why a smooth surface could not be built (the caller draws the coarse mesh instead).
enum class SmoothSurfaceError : std::uint8_t {
  None,
  NoTriangles,     ///< nothing to refine
  BadLevels,       ///< levels outside [1, kMaxSmoothLevels]
  BadTopology,     ///< OpenSubdiv refused the triangles (e.g. a node out of range)
  SingularLimits,  ///< the nodes' limit weights could not be inverted
};

inline constexpr int kMaxSmoothLevels = 4;

class SmoothSurface {
 public:
  /// The Loop surface through the nodes of `triangles` (indices into the columns of `rest`),
  /// refined `levels` times (1..kMaxSmoothLevels; each level has four times the triangles).
  /// On failure `error` says why and the result is empty.
  static std::optional<SmoothSurface> build(const std::vector<std::array<int, 3>>& triangles,
                                            const Points& rest, int levels,
                                            SmoothSurfaceError* error = nullptr);

  SmoothSurface(SmoothSurface&&) noexcept;
  SmoothSurface& operator=(SmoothSurface&&) noexcept;
  ~SmoothSurface();

  /// Refined vertices and triangles (three vertex indices each, counter-clockwise as the
  /// coarse triangle they lie in).
  int vertexCount() const;
  const std::vector<std::array<int, 3>>& triangles() const { return triangles_; }
  /// For each refined triangle, the index of the coarse triangle (in `triangles` as given to
  /// build) that it subdivides.
  const std::vector<int>& parentTriangles() const { return parent_; }
  /// For each coarse node on the surface, the refined vertex that sits on it; −1 for a node
  /// on no triangle.
  const std::vector<int>& nodeVertices() const { return nodeVertex_; }

  /// The refined vertices for nodes at `nodes` (3 values per node, x y z, in node order; at
  /// least as many nodes as the surface uses): 3 values per refined vertex into `out`.
  /// The surface passes through every node.
  void place(const float* nodes, std::vector<float>& out) const;
  void place(const Points& nodes, Points& out) const;

  /// A smooth blend of per-node values (`channels` floats per node, node order) onto the
  /// refined vertices: Loop's own weights, all positive, so a blend of colours stays within
  /// the colours blended (it does not pass through them exactly).
  void blend(const std::vector<float>& perNode, int channels, std::vector<float>& out) const;

 private:
  struct Weights;
  SmoothSurface();

  std::vector<std::array<int, 3>> triangles_;
  std::vector<int> parent_;
  std::vector<int> nodeVertex_;
  std::unique_ptr<Weights> weights_;
};

}  // namespace microsim::sim
