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
// passed fully through in one substep (apart again at its end) is caught continuously: the
// closest points of the start, carried to the end, are closer than 2r along the start's
// separating direction (or on its far side), and are pushed back by the whole amount.
//
// Cost. Every pass first boxes the chain in blocks of 16 nodes (ChainBlocks, swept over the
// substep): a capsule or a surface only visits the nodes of the blocks its box reaches, and
// self-contact skips runs of the chain that are too straight to touch themselves
// (SelfContact). A thread that touches nothing costs O(#nodes) per pass.
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
/// Nodes freeFirst..freeLast, and the links touching them, pass through it: the thread its
/// jaws hold lies inside them.
struct Capsule {
  Vec3 a = Vec3::Zero();
  Vec3 b = Vec3::Zero();
  double radius = 0.0;
  int freeFirst = 0;
  int freeLast = -1;
};

/// Turns wound on a forceps' jaws, kept on them: nodes first..last lie in a shell round the
/// jaws' hull, outside it by the thread's radius and by no more than `slack` beyond that. The
/// hull is the jaws' capsules (as the thread meets them) and the slab between them: the
/// triangle their axes span (they meet at the hinge; closed jaws make it a segment), as thick
/// as the thinnest capsule, so a turn round opened jaws lies round both, not between them (mm).
///
/// Why two-sided. Turns held on the jaws by one-sided contact and friction alone came off as
/// the jaws opened to take the tail or moved to it (one of two turns lost on the shipped
/// instrument-tie scene, issue 19): nothing kept a turn that went slack on the jaws, and a
/// loose turn slides over a tip 0.1 mm across. Wound thread lies on the jaws until it is drawn
/// off past their tips, where the shell ends (the caller leaves out nodes past the tips).
struct Sleeve {
  std::array<Capsule, 4> jaws;
  Vec3 hinge = Vec3::Zero();
  Vec3 tipA = Vec3::Zero();
  Vec3 tipB = Vec3::Zero();
  double slabRadius = 0.0;
  double slack = 0.0;
  int first = 0;
  int last = -1;
};

/// Where a point lies against a sleeve's hull: how far outside its surface (negative: inside),
/// and the way out of it there (unit).
struct HullOffset {
  double distance = 0.0;
  Vec3 normal = Vec3::UnitZ();
};

/// The offset of p from the hull of `sleeve` (the nearest of its capsules and its slab); a
/// point on the slab's plane between the jaws goes out on the side of `side`.
HullOffset hullOffset(const Sleeve& sleeve, const Vec3& p, const Vec3& side);

/// Keeps the movable nodes of each sleeve's run in its shell, with friction μ against their
/// motion since xStart (as capsules do). Marks corrected nodes in `touched`; returns how many.
int projectSleeves(Points& x, const Points& xStart, std::span<const Sleeve> sleeves, double radius,
                   double friction, std::span<const std::uint8_t> movable,
                   std::vector<std::uint8_t>& touched);

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

/// Axis-aligned boxes over runs of kNodes consecutive nodes, each also enclosing the run's
/// next node (so a block covers its links), swept from xStart to x and grown by a margin (mm):
/// the broad phase of every contact pass. O(#nodes) to compute.
struct ChainBlocks {
  static constexpr int kNodes = 16;
  std::vector<collide::Aabb> boxes;
  /// Recomputes the boxes; with xStart null, boxes of x alone.
  void update(const Points& x, const Points* xStart, double margin);
  int count() const { return static_cast<int>(boxes.size()); }
  static int firstNode(int block) { return block * kNodes; }
};

/// What a contact pass did.
struct ContactCounts {
  int nodes = 0;  ///< node corrections
  int pairs = 0;  ///< self-contact link pairs corrected
};

/// Pushes movable nodes (movable[i] != 0) and the intact links between them (alive[l] != 0;
/// empty: all) out of the capsules to distance `radius`, with friction μ against their motion
/// since xStart. A link whose interior is inside is moved along the normal
/// (its nodes by their barycentric weights, as self-contact does), to the side it came from.
/// Marks corrected nodes in `touched`. `scratch` (optional) keeps the broad phase's boxes.
int projectCapsuleContacts(Points& x, const Points& xStart, std::span<const Capsule> capsules,
                           double radius, double friction, std::span<const std::uint8_t> movable,
                           std::vector<std::uint8_t>& touched, ChainBlocks* scratch = nullptr,
                           std::span<const std::uint8_t> alive = {});

/// Pushes movable nodes out of the surface to distance `radius` and back across any face
/// their substep motion crossed from its front, with friction μ. Marks corrected nodes.
int projectSurfaceContacts(Points& x, const Points& xStart, const ContactSurface& surface,
                           double radius, double friction, std::span<const std::uint8_t> movable,
                           std::span<const ContactExemption> exemptions,
                           std::vector<std::uint8_t>& touched, ChainBlocks* scratch = nullptr);

/// Self-contact of the chain with itself, culled by straightness.
///
/// Broad phase: the links in blocks of ChainBlocks::kNodes, a box per block (swept over the
/// substep, as are the links' boxes, and a bounding sphere per link: its midpoint now, half
/// its length plus its nodes' larger motion since xStart, so it holds the link over the whole
/// substep; a pair must meet in both). A run of links
/// whose every link advances along the run's chord d by at least m, (x_{k+1} − x_k)·d ≥ m > 0,
/// cannot touch itself: for links i < j, every point of j lies at least (j − i − 1)·m further
/// along d than every point of i, so pairs at least `skip` links apart are (skip − 1)·m ≥ 2r
/// apart. A block, a pair of neighbouring blocks, an unbroken chain straight at both ends of
/// the substep is skipped whole; other block pairs whose boxes (grown by r) overlap are tested link by link.
class SelfContact {
 public:
  SelfContact() = default;
  explicit SelfContact(int linkCount);
  /// Keeps intact links at least 2·radius apart (pairs fewer than `skip` links apart along
  /// the chain are ignored), with friction μ on their relative tangential motion. Marks the
  /// nodes of corrected pairs in `touched` when given (#nodes entries).
  int project(Points& x, const Points& xStart, double radius, double friction, int skip,
              std::span<const std::uint8_t> movable, const std::vector<std::uint8_t>& alive,
              std::vector<std::uint8_t>* touched = nullptr);
  int linkCount() const { return links_; }

 private:
  bool straight(const Points& x, int firstLink, int endLink, double gap, int skip) const;
  void collect(const Points& x, const Points& xStart, double radius, int skip,
               const std::vector<std::uint8_t>& alive);

  int links_ = 0;
  ChainBlocks blocks_;
  struct Sphere {
    Vec3 centre = Vec3::Zero();
    double radius = 0.0;
  };
  std::vector<collide::Aabb> linkBoxes_;
  std::vector<Sphere> linkSpheres_;  // per link: every point of it over the substep, grown by r
  std::vector<std::uint8_t> straight_;  // per block, then per neighbouring pair
  std::vector<std::array<int, 2>> pairs_;
};

}  // namespace microsim::sim::suture
