#pragma once
// Micro-forceps: two rigid jaws hinged on the tool axis, driven by a pose and a closure.
//
// Tool frame. The origin is the tool tip (the point the tracker reports, where the jaw tips
// meet when closed); +x runs back along the jaws to the hinge at (L, 0, 0), L the jaw length;
// the jaws open in the ±y direction. A jaw mesh (ForcepsDef::jawVertices) lies in its own
// frame with its tip at the origin and its body along +x; the upper jaw is that mesh turned
// about the hinge by −θ about z, the lower jaw the mesh mirrored in y and turned by +θ:
//     θ = (1 − closure) · opening,      tip_upper = (L − L cos θ,  L sin θ, 0),
//                                       tip_lower = (L − L cos θ, −L sin θ, 0).
//
// Grabbing. The jaws hold from closure ≥ closeAt. On the frame the closure reaches it, the
// forceps takes what lies between its tips: every point within grabRadius of the segment
// tip_upper–tip_lower (tipGrabSegment). Held tissue nodes become control nodes that keep
// their offset in the tool frame (they move with the forceps); held suture nodes become a
// hard constraint of the suture (a grip; on the needle an oriented one that also fixes the
// needle's rotation relative to the jaws). When the closure drops below closeAt everything
// is released. A forceps holds the suture in preference to tissue (a needle held above the
// wall must not pinch the wall too).
//
// Units: millimetres, radians inside (degrees in the def).

#include "microsim/sim/mesh/spring_model.h"
#include "microsim/sim/scene/scene_def.h"
#include "microsim/sim/suture/suture_constraints.h"

#include <Eigen/Geometry>

#include <array>
#include <optional>
#include <vector>

namespace microsim::sim::tools {

/// Jaw length L (mm): the jaw mesh's extent along +x.
double jawLength(const ForcepsDef& def);
/// Jaw opening angle θ (rad) at `closure` (0 open .. 1 closed).
double jawAngle(const ForcepsDef& def, double closure);
/// Each jaw's transform, jaw frame → scene: [0] upper, [1] lower (mirrored in y).
std::array<Eigen::Isometry3d, 2> jawPoses(const ForcepsDef& def, const Eigen::Isometry3d& pose,
                                          double closure);
/// The two jaw tips in the scene (mm): [0] upper, [1] lower.
std::array<Vec3, 2> jawTips(const ForcepsDef& def, const Eigen::Isometry3d& pose, double closure);
/// Both jaws' vertices in the scene, upper jaw first (3 by 2·#V, mm); triangles of the lower
/// jaw index the second half with their winding reversed (see jawTriangles).
Points jawVertices(const ForcepsDef& def, const Eigen::Isometry3d& pose, double closure);
std::vector<std::array<int, 3>> jawTriangles(const ForcepsDef& def);

/// Columns of `x` within `radius` of the segment (a, b), in index order; `skip` (may be
/// empty) marks columns to leave out (fixed nodes).
std::vector<int> pointsNearSegment(const Points& x, const Vec3& a, const Vec3& b, double radius,
                                   const std::vector<std::uint8_t>& skip = {});

/// A forceps in use: its def, its last pose and closure, and what it holds.
class Forceps {
 public:
  explicit Forceps(const ForcepsDef& def) : def_(def) {}

  const ForcepsDef& def() const { return def_; }
  const Eigen::Isometry3d& pose() const { return pose_; }
  double closure() const { return closure_; }
  bool closed() const { return closure_ >= def_.closeAt; }

  /// Moves the tool. Returns true when this frame crossed closeAt upwards (time to grab)
  /// and sets `released` when it crossed downwards.
  bool update(const Eigen::Isometry3d& pose, double closure, bool& released);

  /// The segment between the tips now.
  std::array<Vec3, 2> tips() const { return jawTips(def_, pose_, closure_); }

  /// Takes hold of tissue nodes `nodes` at positions x (offsets kept in the tool frame).
  void holdTissue(const std::vector<int>& nodes, const Points& x);
  /// Takes hold of suture node `node` at `position`; `needle` with `needleRotation` (needle
  /// frame → scene) holds the needle's pose too.
  void holdSuture(int node, const Vec3& position, bool needle,
                  const Eigen::Matrix3d& needleRotation);
  void release();

  const std::vector<int>& heldNodes() const { return nodes_; }
  bool holdsSuture() const { return sutureNode_ >= 0; }
  int heldSutureNode() const { return sutureNode_; }
  /// Where the held tissue nodes must be now (scene frame), in heldNodes() order.
  Points heldTargets() const;
  /// The suture grip for this frame, if the forceps holds the suture.
  std::optional<suture::Grip> grip() const;

 private:
  ForcepsDef def_;
  Eigen::Isometry3d pose_ = Eigen::Isometry3d::Identity();
  double closure_ = 0.0;
  std::vector<int> nodes_;
  Points offsets_{3, 0};  // tool frame
  int sutureNode_ = -1;
  bool needle_ = false;
  Vec3 sutureOffset_ = Vec3::Zero();
  Eigen::Matrix3d needleRelative_ = Eigen::Matrix3d::Identity();  // needle → tool frame
};

}  // namespace microsim::sim::tools
