#pragma once
// What lies between the forceps' jaws as they close: the grasp is geometric (DESIGN.md: jaws
// close on whatever surface, needle or thread lies between them).
//
// The region. Each jaw is a rigid body hinged at (L, 0, 0) of the tool frame (forceps.h);
// its gripping face is the plane through its axis (the jaw frame's x axis, tip to heel) and
// the jaw frame's z axis, facing the other jaw. As the jaws close from an angle θ to 0, each
// axis sweeps about the hinge, so what they close on is the circular sector of radius L
// about the hinge between the two axes at θ (the tips run along its arc), as wide out of
// the jaw plane as the jaws' gripping faces: a half-width w growing linearly from the tip's
// to the heel's (the jaw mesh's largest |z| near either end, jawHalfWidths). θ is the angle
// the jaws had on the frame before they closed (Forceps::closedFrom): a keyboard that snaps
// from open to closed sweeps the whole opening, a tracker that closes over several frames
// the last sliver.
//   The region is a convex polyhedron (θ < 90°): the two gripping planes, two planes
// bounding |z| ≤ w(x), and the arc replaced by planes tangent to it at five angles evenly
// between the two axes (the corners between tangents lie at most L (1/cos(θ/4) − 1) beyond
// the arc: 0.011 mm for the shipped 3 mm jaws at the full 20°). Every plane is pushed out by
// a margin: the radius of what is being grasped (the suture's contact radius: a thread that
// touches the region is between the jaws), 0 for the tissue's surface.
//
// Tissue. Every surface face is clipped against the region (Sutherland–Hodgman in
// barycentric coordinates, which the planes' signed distances are affine in, so the clip is
// exact); a face with a part of positive area inside is held at that part's centroid, a
// barycentric point of the face, and carries the part's area (the forceps shares its hold
// stiffness by area: forceps.h).
//
// Suture. Every intact link is clipped against the region; the jaws take the point of the
// clipped pieces nearest the line where the jaws meet (the tool axis from the tip to the
// hinge), the lowest link on ties: a needle across the jaws is held where it crosses them.
//
// Units: millimetres.

#include "microsim/sim/mesh/spring_model.h"
#include "microsim/sim/scene/scene_def.h"

#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace microsim::sim::tools {

/// A half-space n·p ≤ offset (n unit, offset in mm).
struct GraspPlane {
  Vec3 normal = Vec3::UnitX();
  double offset = 0.0;
};

/// The space between the jaws (header essay), in the scene frame.
struct GraspRegion {
  std::vector<GraspPlane> planes;
  Vec3 axisTip = Vec3::Zero();   ///< where the jaw tips meet (the tool tip), mm
  Vec3 axisHeel = Vec3::Zero();  ///< the hinge, mm
  Vec3 boxLow = Vec3::Zero();    ///< a box around the region, mm
  Vec3 boxHigh = Vec3::Zero();
};

/// The half-width of the jaws' gripping faces out of the jaw plane at the tip and at the heel
/// (mm): the jaw mesh's largest |z| within a tenth of its length of either end.
std::array<double, 2> jawHalfWidths(const ForcepsDef& def);

/// The region between the jaws of `def` at `pose` closing from `closure` (0 open .. 1 closed),
/// every plane pushed out by `margin` (mm).
GraspRegion graspRegion(const ForcepsDef& def, const Eigen::Isometry3d& pose, double closure,
                        double margin);

/// True when p lies in the region (on its boundary included).
bool insideGraspRegion(const GraspRegion& region, const Vec3& p);

/// A tissue face between the jaws: the centroid of its part inside, and that part's area.
struct FaceGrasp {
  int face = -1;
  Vec3 barycentric = Vec3::Zero();  ///< on the face's corners, sum 1
  double area = 0.0;                ///< mm²
};

/// The surface faces of `tissue` at positions x with a part of positive area in the region,
/// in face order. A face with a corner marked in `skip` (may be empty) is left out, and so
/// is a face whose corners are all fixed (nothing of it can move).
std::vector<FaceGrasp> facesBetweenJaws(const GraspRegion& region, const SpringModel& tissue,
                                        const Points& x, const std::vector<std::uint8_t>& skip = {});

/// The point of a chain the jaws take: `fraction` along link `link` (nodes link, link + 1),
/// at `distance` from the line where the jaws meet.
struct ChainGrasp {
  int link = -1;
  double fraction = 0.0;  ///< [0, 1]
  double distance = 0.0;  ///< mm
};

/// The point of the chain x (links i: nodes i, i + 1; `alive` per link, may be empty: all
/// intact) in the region nearest the line where the jaws meet; none when no link reaches it.
std::optional<ChainGrasp> chainPointBetweenJaws(const GraspRegion& region, const Points& x,
                                                const std::vector<std::uint8_t>& alive = {});

}  // namespace microsim::sim::tools
