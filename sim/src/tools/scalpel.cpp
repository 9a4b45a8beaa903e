#include "microsim/sim/tools/scalpel.h"

#include <algorithm>
#include <array>

namespace microsim::sim::tools {

namespace {

std::vector<std::array<int, 2>> linkSegments(const SpringModel& tissue) {
  std::vector<std::array<int, 2>> out;
  out.reserve(tissue.links().size());
  for (const Link& l : tissue.links()) out.push_back({l.a, l.b});
  return out;
}

// blade vertices: 0..3 the blade now (tip, heel, heel top, tip top), 4..5 the edge before
constexpr std::array<std::array<int, 3>, 4> kBladeTriangles{
    {{0, 1, 2}, {0, 2, 3}, {4, 5, 1}, {4, 1, 0}}};

}  // namespace

Points bladeCorners(const ScalpelDef& def, const Eigen::Isometry3d& pose) {
  Points out(3, 4);
  out.col(0) = pose * Vec3::Zero();
  out.col(1) = pose * Vec3(def.bladeLength, 0.0, 0.0);
  out.col(2) = pose * Vec3(def.bladeLength, 0.0, def.bladeHeight);
  out.col(3) = pose * Vec3(0.0, 0.0, def.bladeHeight);
  return out;
}

template <class Volume>
LinkCutter<Volume>::LinkCutter(const SpringModel& tissue, const Points& x) {
  const auto segments = linkSegments(tissue);
  if (!segments.empty()) links_ = collide::BvhTree<Volume>::overSegments(segments, x);
  bladeX_.setZero();
  blade_ = collide::BvhTree<Volume>::overTriangles(kBladeTriangles, bladeX_);
}

template <class Volume>
void LinkCutter<Volume>::maintain(const std::vector<int>& moved, const Points& x) {
  if (!moved.empty() && !links_.empty()) links_.maintainVertices(moved, x);
}

template <class Volume>
std::vector<int> LinkCutter<Volume>::cut(SpringModel& tissue, const Points& x,
                                         const ScalpelDef& def, const Eigen::Isometry3d* from,
                                         const Eigen::Isometry3d& to) {
  std::vector<int> cutLinks;
  if (links_.empty()) return cutLinks;

  // the blade now and the edge it swept (degenerate when it did not move)
  bladeX_.leftCols(4) = bladeCorners(def, to);
  if (from) {
    const Points before = bladeCorners(def, *from);
    bladeX_.col(4) = before.col(0);
    bladeX_.col(5) = before.col(1);
  } else {
    bladeX_.col(4) = bladeX_.col(0);
    bladeX_.col(5) = bladeX_.col(1);
  }
  blade_.refitAll(bladeX_);
  collide::allPairs(blade_, bladeX_, links_, x, pairs_);

  // every alive crossed link, once, in index order
  for (const collide::FeaturePair& p : pairs_)
    if (tissue.link(p.second).alive) cutLinks.push_back(p.second);
  std::sort(cutLinks.begin(), cutLinks.end());
  cutLinks.erase(std::unique(cutLinks.begin(), cutLinks.end()), cutLinks.end());
  for (int l : cutLinks) tissue.removeLink(l);
  return cutLinks;
}

template class LinkCutter<collide::Sphere>;
template class LinkCutter<collide::Aabb>;

}  // namespace microsim::sim::tools
