#pragma once
// The tissue's surface as the viewport draws it, measured for `bench scene`: how many points and
// triangles, what placing it costs a frame, and how smooth it looks (issue 17, item 5: a coarse
// simulation drawn through a smooth surface must look as smooth as a mesh ten times denser).
//
// Smoothness is the fold between neighbouring drawn triangles: the angle between their normals
// across each shared edge, over every edge that is not a crease. A crease is an edge whose
// faces meet at more than sim::kCreaseAngleDeg at rest (a cut face against its walls): those
// are meant to be sharp. A faceted tube of P sides folds 360°/P at every edge along it.
//
// The drawn surface is the scene's triangles over its nodes, or with def.surface.subdivision
// the smooth surface through them (sim::SmoothSurface), as app/gui/render/tissue_surface.h
// builds it (without the end faces' copies, which change no position). Placing includes the
// area-weighted vertex normals the viewport needs either way.

#include "microsim/sim/mesh/smooth_surface.h"
#include "microsim/sim/scene/scene_def.h"

#include <array>
#include <memory>
#include <utility>
#include <vector>

namespace microsim::bench {

class DrawnSurface {
 public:
  DrawnSurface(const sim::SceneDef& def, const std::vector<std::array<int, 3>>& triangles);

  int pointCount() const { return points_; }
  int triangleCount() const { return static_cast<int>(triangles_->size()); }
  bool smooth() const { return smooth_ != nullptr; }

  /// Places the drawn points and their normals for tissue nodes at `x`.
  void place(const sim::Points& x);
  /// The folds (degrees) of the last placed surface: its p99 and largest.
  std::pair<double, double> folds() const;

 private:
  std::unique_ptr<sim::SmoothSurface> smooth_;
  const std::vector<std::array<int, 3>>* triangles_ = nullptr;
  int points_ = 0;
  std::vector<std::array<int, 2>> edgeFaces_;  ///< the two triangles of each non-crease edge
  sim::Points placed_;
  std::vector<float> xyz_, normals_;
};

}  // namespace microsim::bench
