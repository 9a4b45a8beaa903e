#pragma once
// Contacts of the suture with rigid capsules (forceps jaws), with triangle surfaces (the
// vessel, any draping support) and with itself, as position projections (PBD style) with
// Coulomb friction.
//
// Every kernel works on one substep: xStart holds the positions at its beginning (known to be
// outside every obstacle), x the positions being corrected. A node closer than the thread's
// radius r to an obstacle is pushed out to distance r along the obstacle's outward direction
// by a correction δn; its tangential motion since xStart, t, is then cancelled when
// |t| ≤ μ δn (static friction, the node sticks) or shortened by μ δn (sliding friction). That
// position-level friction is what makes turns wrapped around a jaw hold while the free end is
// pulled: the pull presses the turns onto the jaw, and the normal correction bounds the
// tangential slip (a discrete capstan).
//
// No tunnelling. Capsules are thick (a jaw is ~0.1 mm against link motions of a few µm per
// substep), so a discrete test suffices. Surfaces are thin (a vessel wall): each node's motion
// xStart → x is also tested as a segment against the triangles near it, and a node that
// crossed a face from its front side is put back on the front at distance r from the hit.
// Self-contact: link pairs closer than 2r are pushed apart along their separating direction
// at xStart (evaluated at the current closest parameters), so a pair that ended a substep
// crossed is pushed back to the side it came from; the push is capped at 4r. A pair that
// passes fully through in one substep (more than 2r beyond) is not seen: substeps keep the
// motion per substep below that at hand speeds.
//
// Faces point out of the material (the vessel generator's convention): "front" is the side the
// normal points to. Units: millimetres; positions 3 by #nodes.

#include "microsim/sim/collide/sphere_tree.h"
#include "microsim/sim/collide/tree_queries.h"
#include "microsim/sim/suture/suture_model.h"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace microsim::sim::suture {

/// A capsule: all points within `radius` of the segment (a, b) (mm). A forceps jaw.
struct Capsule {
  Vec3 a = Vec3::Zero();
  Vec3 b = Vec3::Zero();
  double radius = 0.0;
};

/// Nodes in [firstNode, lastNode] ignore `face` and the faces sharing a vertex with it
/// (the suture passes through a pierced face).
struct ContactExemption {
  int firstNode = 0;
  int lastNode = -1;
  int face = -1;
};

/// A triangle surface the suture rests on, with its bounding-volume tree over the faces.
class ContactSurface {
 public:
  ContactSurface() = default;
  /// Faces index columns of x (3 by #V, mm), wound so normals point out of the material.
  ContactSurface(std::vector<std::array<int, 3>> triangles, const Points& x);
  /// New vertex positions (same count): refits the tree.
  void update(const Points& x);

  const Points& positions() const { return x_; }
  const std::vector<std::array<int, 3>>& triangles() const { return triangles_; }
  const collide::AabbTree& tree() const { return tree_; }
  /// True when faces f and g share a vertex (or f == g).
  bool touching(int f, int g) const;
  bool empty() const { return triangles_.empty(); }

 private:
  std::vector<std::array<int, 3>> triangles_;
  Points x_{3, 0};
  collide::AabbTree tree_;
};

/// What a contact pass did.
struct ContactCounts {
  int nodes = 0;  ///< node corrections
  int pairs = 0;  ///< self-contact link pairs corrected
};

/// Pushes movable nodes (movable[i] != 0) out of the capsules to distance `radius`, with
/// friction μ against their motion since xStart. Marks corrected nodes in `touched`.
int projectCapsuleContacts(Points& x, const Points& xStart, std::span<const Capsule> capsules,
                           double radius, double friction, std::span<const std::uint8_t> movable,
                           std::vector<std::uint8_t>& touched);

/// Pushes movable nodes out of the surface to distance `radius` and back across any face
/// their substep motion crossed from its front, with friction μ. Marks corrected nodes.
int projectSurfaceContacts(Points& x, const Points& xStart, const ContactSurface& surface,
                           double radius, double friction, std::span<const std::uint8_t> movable,
                           std::span<const ContactExemption> exemptions,
                           std::vector<std::uint8_t>& touched);

/// Self-contact through a tree over the chain's links (fixed topology, refit per call).
class SelfContact {
 public:
  SelfContact() = default;
  explicit SelfContact(int linkCount);
  /// Keeps intact links at least 2·radius apart (pairs fewer than `skip` links apart along
  /// the chain are ignored), with friction μ on their relative tangential motion.
  int project(Points& x, const Points& xStart, double radius, double friction, int skip,
              std::span<const std::uint8_t> movable, const std::vector<std::uint8_t>& alive);
  int linkCount() const { return static_cast<int>(segments_.size()); }

 private:
  std::vector<std::array<int, 2>> segments_;
  collide::AabbTree tree_;
  std::vector<collide::FeaturePair> pairs_;
};

}  // namespace microsim::sim::suture
