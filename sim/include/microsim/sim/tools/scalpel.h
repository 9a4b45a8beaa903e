#pragma once
// Scalpel: links crossed by the blade are removed (SpringModel::removeLink).
//
// The blade is the rectangle [0, length] × {0} × [0, height] of the tool frame (ScalpelDef);
// its cutting edge is the x axis from the tip. A step cuts every alive link that meets
//   - the blade at its new pose (two triangles), or
//   - the surface the cutting edge swept since the last step (the quad between the old and
//     the new edge, two triangles),
// so a blade moving faster than a link's length per step still cuts everything it passed.
// Links are found through a segment tree over every link of the tissue (fixed topology: a
// cut link stays in the tree and is skipped), tested against a four-triangle blade tree by
// the exact segment–triangle test. Cutting keeps every index valid (removeLink only marks
// the link dead), so solvers, node orderings and trees stay valid; the caller resets the
// tissue solver's caches.
//
// Units: millimetres.

#include "microsim/sim/collide/sphere_tree.h"
#include "microsim/sim/collide/tree_queries.h"
#include "microsim/sim/mesh/spring_model.h"
#include "microsim/sim/scene/scene_def.h"

#include <Eigen/Geometry>

#include <vector>

namespace microsim::sim::tools {

/// The blade's corners in the scene: tip, heel of the edge, heel top, tip top (3 by 4, mm).
Points bladeCorners(const ScalpelDef& def, const Eigen::Isometry3d& pose);

template <class Volume>
class LinkCutter {
 public:
  LinkCutter() = default;
  /// A segment tree over every link of `tissue` at positions x.
  LinkCutter(const SpringModel& tissue, const Points& x);

  /// Refits the links around the moved nodes.
  void maintain(const std::vector<int>& moved, const Points& x);
  /// Removes the alive links the blade crosses going from `from` to `to` (see the essay);
  /// returns them in index order. `from` empty: only the blade at `to`.
  std::vector<int> cut(SpringModel& tissue, const Points& x, const ScalpelDef& def,
                       const Eigen::Isometry3d* from, const Eigen::Isometry3d& to);

 private:
  collide::BvhTree<Volume> links_;
  collide::BvhTree<Volume> blade_;
  Points bladeX_{3, 6};
  std::vector<collide::FeaturePair> pairs_;
};

extern template class LinkCutter<collide::Sphere>;
extern template class LinkCutter<collide::Aabb>;

}  // namespace microsim::sim::tools
