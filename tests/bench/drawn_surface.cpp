#include "drawn_surface.h"

#include "microsim/sim/scene/render_snapshot.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

namespace microsim::bench {

namespace {

sim::Vec3 faceNormal(const sim::Points& x, const std::array<int, 3>& t) {
  const sim::Vec3 n = (x.col(t[1]) - x.col(t[0])).cross(x.col(t[2]) - x.col(t[0]));
  return n.norm() > 0.0 ? sim::Vec3(n.normalized()) : sim::Vec3::Zero();
}

}  // namespace

DrawnSurface::DrawnSurface(const sim::SceneDef& def,
                           const std::vector<std::array<int, 3>>& triangles)
    : triangles_(&triangles) {
  const sim::Points& rest = def.tissue.model.restPositions();
  if (def.surface.subdivision > 0)
    if (auto s = sim::SmoothSurface::build(triangles, rest, def.surface.subdivision)) {
      smooth_ = std::make_unique<sim::SmoothSurface>(std::move(*s));
      triangles_ = &smooth_->triangles();
    }
  if (smooth_) {
    points_ = smooth_->vertexCount();
  } else {
    std::vector<bool> used(static_cast<std::size_t>(rest.cols()), false);
    for (const auto& t : triangles)
      for (int n : t) used[static_cast<std::size_t>(n)] = true;
    points_ = static_cast<int>(std::count(used.begin(), used.end(), true));
  }

  // the edges that may fold: those whose faces meet at less than a crease's angle at rest
  place(rest);
  std::map<std::pair<int, int>, std::vector<int>> faces;
  for (std::size_t f = 0; f < triangles_->size(); ++f)
    for (std::size_t k = 0; k < 3; ++k) {
      const int a = (*triangles_)[f][k];
      const int b = (*triangles_)[f][(k + 1) % 3];
      faces[{std::min(a, b), std::max(a, b)}].push_back(static_cast<int>(f));
    }
  const double crease = std::cos(sim::kCreaseAngleDeg * std::numbers::pi / 180.0);
  for (const auto& [edge, around] : faces) {
    if (around.size() != 2) continue;
    const sim::Vec3 n0 = faceNormal(placed_, (*triangles_)[static_cast<std::size_t>(around[0])]);
    const sim::Vec3 n1 = faceNormal(placed_, (*triangles_)[static_cast<std::size_t>(around[1])]);
    if (n0.dot(n1) >= crease) edgeFaces_.push_back({around[0], around[1]});
  }
}

void DrawnSurface::place(const sim::Points& x) {
  if (smooth_)
    smooth_->place(x, placed_);
  else
    placed_ = x;
  xyz_.resize(3 * static_cast<std::size_t>(placed_.cols()));
  for (Eigen::Index p = 0; p < placed_.cols(); ++p)
    for (Eigen::Index c = 0; c < 3; ++c)
      xyz_[static_cast<std::size_t>(3 * p + c)] = static_cast<float>(placed_(c, p));
  sim::vertexNormals(xyz_, *triangles_, normals_);
}

std::pair<double, double> DrawnSurface::folds() const {
  std::vector<double> degrees;
  degrees.reserve(edgeFaces_.size());
  for (const auto& [f0, f1] : edgeFaces_) {
    const sim::Vec3 n0 = faceNormal(placed_, (*triangles_)[static_cast<std::size_t>(f0)]);
    const sim::Vec3 n1 = faceNormal(placed_, (*triangles_)[static_cast<std::size_t>(f1)]);
    if (n0.isZero() || n1.isZero()) continue;
    degrees.push_back(std::acos(std::clamp(n0.dot(n1), -1.0, 1.0)) * 180.0 / std::numbers::pi);
  }
  if (degrees.empty()) return {0.0, 0.0};
  std::sort(degrees.begin(), degrees.end());
  const auto rank = static_cast<std::size_t>(std::ceil(0.99 * static_cast<double>(degrees.size())));
  return {degrees[std::max<std::size_t>(rank, 1) - 1], degrees.back()};
}

}  // namespace microsim::bench
