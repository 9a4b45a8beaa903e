#pragma once
// Needle pierces: the needle's tip crossing a tissue face.
//
// Each step the tip moves from p (its position before the suture stepped) to q (after). Every
// tissue face the segment p→q crosses is a pierce, found continuously (no tunnelling, however
// fast the hand): a one-segment tree of the tip's path is tested against the collision tree of
// the tissue faces, then each candidate face by the exact segment–triangle test. Faces point
// out of the material, so the sign of (q − p)·n tells the two kinds apart:
//     entry: (q − p)·n < 0   the tip goes into the wall material through the face's front;
//     exit:  (q − p)·n > 0   the tip leaves the material through it.
// Crossings are reported in order along the path (by t, then face index); a crossing that
// lands on an edge or vertex shared by several faces of one surface is reported once (the
// lowest face index at the same t and side). The tissue tree is kept current by the caller
// (maintainVertices with the nodes that moved).
//
// Faces that move over the tip. The tissue moves in its own solve, after the tip's path was
// tested, and a face dragged along the needle (a wall the thread holds) can sweep over the
// standing tip. passedOver finds those: for each face within reach of the tip, the tip's
// signed distance to the face's plane before and after the solve, s₀ and s₁; where the sign
// changes, the face is interpolated to where it met the tip (λ = s₀/(s₀ − s₁)), and the tip's
// projection on it must lie in the triangle. Seen from the tissue the tip went in through the
// face's front when s₀ > 0 ≥ s₁ (an entry) and out of it when s₀ < 0 ≤ s₁ (an exit).
//
// Angles. The needle's tangent at the tip, τ, is the direction the tip travels along the
// needle's shape (for the curved needle, the rest-shape tangent at node 0 rotated by the
// needle's current rotation; for a straight one the tip link). A pierce's angle is taken where
// the needle's body passes through the hole, not at the tip: the tangent of the needle's arc
// at its point nearest the hole (the circle through the needle's nodes, R the needle radius,
// centre at the tip + R·r̂ with r̂ the rest shape's inward normal at the tip, turned like the
// needle; the point is clamped to the arc, tip to swage). Where the tip has gone on past the
// hole (a wall dented before its puncture, the tip turning along its curve meanwhile) the tip's
// own tangent would lean by the angle turned since the touch (5–8° at lesson 2's marks). The
// pierce angle is the angle between that tangent and the face normal's line, acos |τ·n| in
// degrees: 0° is perpendicular to the wall (the ideal bite), 90° is grazing.
//
// Units: millimetres, degrees.

#include "microsim/sim/collide/sphere_tree.h"
#include "microsim/sim/collide/tree_queries.h"
#include "microsim/sim/mesh/spring_model.h"
#include "microsim/sim/suture/suture_model.h"

#include <array>
#include <vector>

namespace microsim::sim::tools {

/// One face crossing of the tip's path.
struct FaceCrossing {
  int face = -1;
  double t = 0.0;                   ///< along the path p + t (q − p), [0, 1]
  Vec3 point = Vec3::Zero();        ///< mm
  Vec3 barycentric = Vec3::Zero();  ///< on the face's corners, sum 1
  Vec3 normal = Vec3::Zero();       ///< unit face normal (out of the material)
  bool entry = true;                ///< into the material (see the header essay)
};

/// Unit normal of tissue face `face` at positions x (zero for a degenerate face).
Vec3 faceNormal(const SpringModel& tissue, const Points& x, int face);

/// The needle's forward tangent at its tip (unit): see the header essay.
Vec3 needleTipTangent(const suture::SutureModel& model, const suture::Points& x);

/// The needle's forward tangent (unit, towards the tip) at the point of its arc nearest p:
/// see the header essay (the tip link's direction for a straight needle).
Vec3 needleTangentNear(const suture::SutureModel& model, const suture::Points& x, const Vec3& p);

/// Angle (degrees) between a direction and a surface normal's line: acos |τ·n|.
double pierceAngleDeg(const Vec3& tangent, const Vec3& normal);

/// Face crossings of the tip path p→q, in path order. Works with either tree type.
template <class Volume>
class PierceDetector {
 public:
  PierceDetector() = default;
  /// A tree over `tissue`'s triangles at positions x.
  PierceDetector(const SpringModel& tissue, const Points& x);

  /// Refits the faces around the moved nodes (every node when `moved` is empty and `all`).
  void maintain(const std::vector<int>& moved, const Points& x);
  /// The crossings of p→q; `out` is cleared first.
  void crossings(const SpringModel& tissue, const Points& x, const Vec3& p, const Vec3& q,
                 std::vector<FaceCrossing>& out);
  /// The faces within `reach` of the standing tip that moved over it from `before` to `x`
  /// (see the header essay; t is 1), in face order; `out` is cleared first.
  void passedOver(const SpringModel& tissue, const Points& before, const Points& x, const Vec3& tip,
                  double reach, std::vector<FaceCrossing>& out);

  const collide::BvhTree<Volume>& tree() const { return tree_; }

 private:
  collide::BvhTree<Volume> tree_;
  collide::BvhTree<Volume> path_;
  Points pathX_{3, 2};
  std::vector<collide::FeaturePair> pairs_;
  std::vector<collide::PointNearFeature> near_;
};

extern template class PierceDetector<collide::Sphere>;
extern template class PierceDetector<collide::Aabb>;

}  // namespace microsim::sim::tools
