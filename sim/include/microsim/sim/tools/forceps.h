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
// Grasping (jaw_grasp.h). The jaws hold from closure ≥ closeAt. On the frame the closure
// reaches it, the forceps takes what lies between its jaws: the region they swept closing
// from the closure of the frame before (closedFrom), as wide as their gripping faces. It
// takes the suture first (a needle held above the wall must not pinch the wall too): the
// point of the needle or thread in the region nearest the line where the jaws meet, which
// becomes a hard constraint of the suture (a grip, suture_constraints.h). On the needle
// anywhere along its body: the grip keeps the point (a needle node, or a fraction along a
// needle link) at its place in the tool frame and the needle's rotation relative to the
// jaws, so the needle moves rigidly with the jaws, and opening and closing again at
// another point or angle re-grasps it there. On the thread anywhere along its length: on a
// node (a ball joint), or between two nodes, the link clamped along its direction in the
// tool frame. A grip point within kGripSnap of a node is taken at the node.
//   Otherwise the tissue: every surface face with a part between the jaws is held at that
// part's centroid, a barycentric point of the face, kept at its place in the tool frame.
// Where the tissue solver takes point springs (point_spring.h) each held point is a
// zero-rest spring to its place, the hold stiffness shared among them by the area inside
// (so a grasp is as stiff however finely the wall is meshed); elsewhere (the paper's qss,
// rk4, implicit) the held faces' corners become control nodes that keep their offsets in
// the tool frame. When the hand's closure drops below closeAt everything is released.
//
// Opening. The jaws close as fast as the hand squeezes, but their spring parts them no faster
// than from closed to open in ForcepsDef::openingSeconds: a hand letting go (or a button that
// jumps the closure to 0) leaves the jaws opening over several steps, so a jaw that opens
// against the wall pushes it aside (jaw_contact.h) instead of appearing a millimetre inside it.
//
// Hold stiffness. ForcepsDef::holdStiffness, 3e5 g/s² for a whole grasp (about the thread's
// axial stiffness, which couples a pierce to its wall), keeps a grasped wall within a small
// fraction of its 0.1 mm thickness of the jaws. Measured on the shipped anastomosis, the wall
// grasped from above and lifted 0.3 mm (lesson 1's stretch) and 0.5 mm: the held patch's lag
// by share, and in brackets its largest (a face the jaws clip a sliver of, whose share is small):
//     hold      lifted 0.3 mm      lifted 0.5 mm
//     1e5       0.004 (0.011) mm   0.009 (0.022) mm
//     3e5       0.002 (0.008)      0.004 (0.016)    (pulling 1.2 mN)
//     1e6       0.001 (0.006)      0.002 (0.011)
// A softer hold lets the wall sag past the 0.01–0.02 mm it allows; a stiffer one gains little
// (the wall between the held points takes the rest) and conditions newton's solve worse
// (tests/sim/tools/forceps_test.cpp, ShippedHoldFollowsTheJawWithinAFractionOfTheWall).
//
// Units: millimetres, radians inside (degrees in the def).

#include "microsim/sim/mesh/point_spring.h"
#include "microsim/sim/mesh/spring_model.h"
#include "microsim/sim/scene/scene_def.h"
#include "microsim/sim/suture/suture_constraints.h"
#include "microsim/sim/tools/jaw_grasp.h"

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

/// mm: a grip point this close to a suture node (along its link) is taken at the node —
/// a pose that meant the node (a script's, a tracker's at a node) reaches it within rounding.
constexpr double kGripSnap = 1e-6;

/// A point of a tissue face the forceps holds.
struct HeldFacePoint {
  int face = -1;
  std::array<int, 3> corners{-1, -1, -1};  ///< the face's nodes
  Vec3 barycentric = Vec3::Zero();          ///< on the corners, sum 1
  Vec3 offset = Vec3::Zero();               ///< where it is kept, tool frame (mm)
  double share = 0.0;                       ///< of the hold stiffness (the shares sum to 1)
};

/// A forceps in use: its def, its last pose and closure, and what it holds.
class Forceps {
 public:
  explicit Forceps(const ForcepsDef& def) : def_(def) {}

  const ForcepsDef& def() const { return def_; }
  const Eigen::Isometry3d& pose() const { return pose_; }
  /// The jaws' closure as drawn and as they meet the tissue (0 open .. 1 closed): the
  /// hand's, except while the jaws are still opening after it let go.
  double closure() const { return closure_; }
  /// Whether the hand squeezes the jaws hard enough to hold (its closure ≥ closeAt).
  bool closed() const { return squeeze_ >= def_.closeAt; }

  /// Moves the tool over a step of `dt` s. The jaws close as fast as `closure` asks but open
  /// no faster than ForcepsDef::openingSeconds allows. Returns true when this frame crossed
  /// closeAt upwards (time to grab) and sets `released` when it crossed downwards.
  bool update(const Eigen::Isometry3d& pose, double closure, double dt, bool& released);
  /// The closure of the frame before the last update: what the jaws closed from.
  double closedFrom() const { return closedFrom_; }

  /// The segment between the tips now.
  std::array<Vec3, 2> tips() const { return jawTips(def_, pose_, closure_); }

  /// Takes hold of the tissue faces `faces` of `tissue` at positions x (header essay).
  void holdTissue(const std::vector<FaceGrasp>& faces, const SpringModel& tissue, const Points& x);
  /// Takes hold of the suture of `model` at positions x at the point `at` (a point within
  /// kGripSnap of a node taken at the node; header essay).
  void holdSuture(const ChainGrasp& at, const suture::SutureModel& model, const Points& x);
  void release();

  /// The held faces' corners that are not fixed, in index order (the nodes a grasp moves).
  const std::vector<int>& heldNodes() const { return nodes_; }
  const std::vector<HeldFacePoint>& heldFaces() const { return faces_; }
  bool holdsSuture() const { return sutureNode_ >= 0; }
  int heldSutureNode() const { return sutureNode_; }
  double heldSutureFraction() const { return sutureFraction_; }
  /// Where the held tissue nodes must be now (scene frame), in heldNodes() order: the hold
  /// for solvers without point springs.
  Points heldTargets() const;
  /// The hold as point springs: each held face point tied to its place now.
  void appendHoldSprings(std::vector<PointSpring>& out) const;
  /// The suture grip for this frame, if the forceps holds the suture.
  std::optional<suture::Grip> grip() const;

 private:
  ForcepsDef def_;
  Eigen::Isometry3d pose_ = Eigen::Isometry3d::Identity();
  double closure_ = 0.0;
  double squeeze_ = 0.0;  // the hand's closure this frame
  double closedFrom_ = 0.0;
  std::vector<HeldFacePoint> faces_;
  std::vector<int> nodes_;
  Points offsets_{3, 0};  // of nodes_, tool frame
  int sutureNode_ = -1;
  double sutureFraction_ = 0.0;
  bool needle_ = false;
  Vec3 sutureOffset_ = Vec3::Zero();
  Eigen::Matrix3d needleRelative_ = Eigen::Matrix3d::Identity();  // needle → tool frame
  Vec3 linkDirection_ = Vec3::Zero();                              // tool frame
};

}  // namespace microsim::sim::tools
