#pragma once
// The suture of Brown et al. 2002 §4: a needle and thread modelled as an articulated chain
// of N short rigid links joined by spherical joints, nodes 0..N. The first `needleLinks`
// links (nodes 0..n, n = needleLinks, node 0 the needle tip, node n the swage where the
// thread is attached) keep their joint angles fixed: a rigid needle, straight or a curved
// 3/8 circle. Links n..N are the thread; node N is the thread's free tail.
//
// The split is MuJoCo's, as for the tissue: SutureModel holds what never changes (rest
// lengths, masses, the needle's shape, contact radius, friction, the breaking threshold);
// SutureState holds what a step advances (positions, the previous positions that carry the
// velocity, which links are broken, where the suture pierces the tissue and at which node).
//
// Needle frame: the needle's rest shape lies in the xy plane with the tip at the origin.
// Curved: node k at angle θ_k = (k/n)·3π/4 on the circle of radius R through the origin,
// p(θ) = (R sin θ, R (1 − cos θ), 0); the tangent at the swage is (cos 3π/4, sin 3π/4, 0).
// Straight: node k at ((k/n)·L, 0, 0). The thread continues straight from the swage along
// the swage tangent, links of length l = length / (N − n).
//
// Units: millimetres, seconds, grams. Positions are 3 by (N + 1).

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <vector>

namespace microsim::sim::suture {

using Vec3 = Eigen::Vector3d;
/// Node positions: 3 by (N + 1), column i is node i (mm).
using Points = Eigen::Matrix3Xd;

enum class NeedleShape : std::uint8_t {
  Straight,  ///< a straight needle of length needleLength
  Curved,    ///< a 3/8 circle of radius needleRadius (arc length 3πR/4)
};

struct SutureDef {
  double length = 20.0;          ///< thread length (mm), needle excluded
  int links = 200;               ///< N: all links, needle links included (≥ needleLinks + 1)
  int needleLinks = 8;           ///< n: links held rigid as the needle (0 = thread only)
  NeedleShape needleShape = NeedleShape::Curved;
  double needleRadius = 1.0;     ///< curved needle radius (mm); a 3/8 circle of it
  double needleLength = 2.5;     ///< straight needle length (mm)
  double breakStretch = 0.05;    ///< over-length between two hard constraints that breaks, relative
  /// over-length of a link in a strand pressed on another (a knot drawn past tight) that,
  /// held for kKnotBreakSeconds, breaks it, relative (knot_strain.h)
  double knotBreakStretch = 0.10;
  /// mm: a passive pierce (the needle still carrying the suture through it) whose point lies
  /// farther than this from the needle has been left by it and is released (suture_constraints.h)
  double pierceReleaseDistance = 0.05;
  double massPerLink = 1e-5;     ///< thread mass per link (g); node i gets half of each link it ends
  double needleMass = 1e-3;      ///< whole needle mass (g), spread over the needle nodes
  double contactRadius = 0.01;   ///< thread radius for contacts (mm)
  double friction = 0.3;         ///< Coulomb friction coefficient μ for every contact (dimensionless)
  double drag = 20.0;            ///< velocity decay rate (1/s): v ← v·exp(−drag·h) each substep
};

/// True when every field is finite and in range.
bool validSutureDef(const SutureDef& def);

class SutureModel {
 public:
  /// The chain `def` describes. `def` must be valid (see validSutureDef).
  explicit SutureModel(const SutureDef& def = {});

  const SutureDef& def() const { return def_; }
  int linkCount() const { return static_cast<int>(rest_.size()); }
  int nodeCount() const { return linkCount() + 1; }
  /// n: nodes 0..n form the rigid needle (n = 0: no needle).
  int needleLinks() const { return def_.needleLinks; }
  /// Index of the swage node (= needleLinks()): first thread node.
  int swage() const { return def_.needleLinks; }
  bool isNeedleNode(int i) const { return i < def_.needleLinks; }

  /// Rest length of link i (nodes i, i + 1), mm.
  double rest(int link) const { return rest_[link]; }
  const std::vector<double>& restLengths() const { return rest_; }
  /// Rest arc length from node i to node j (mm), either order.
  double arc(int i, int j) const;
  /// Inverse mass of node i (1/g).
  double inverseMass(int i) const { return invMass_[i]; }
  const std::vector<double>& inverseMasses() const { return invMass_; }

  /// The needle's rest shape in its own frame: 3 by (n + 1) (mm); see the header essay.
  const Points& needleShape() const { return needle_; }
  /// The whole chain at rest in the needle frame: 3 by (N + 1) (mm).
  const Points& restPositions() const { return restX_; }

  /// Gravity (mm/s²); zero unless a scene asks for it.
  Vec3 gravity = Vec3::Zero();

 private:
  SutureDef def_;
  std::vector<double> rest_;
  std::vector<double> prefix_;  // prefix_[i] = arc length from node 0 to node i
  std::vector<double> invMass_;
  Points needle_{3, 0};
  Points restX_{3, 0};
};

/// A pierce: the suture passes through a tissue face at a point given by the face's
/// barycentric coordinates. It is a soft constraint on chain node `node`, which changes as the
/// suture slides through. While `node` lies on the needle, the pierce is passive (the rigid
/// needle carries the suture through) and `node` tracks the needle node nearest the point
/// (suture_constraints.h: pierces keep their order along the chain).
struct Pierce {
  int face = -1;                   ///< tissue triangle index
  Vec3 barycentric = Vec3::Zero(); ///< (u, v, w) on the face's corners, sum 1
  int node = 0;                    ///< the chain node held at the point
  Vec3 point = Vec3::Zero();       ///< the pierce point (mm), read back from the tissue each step
};

struct SutureState {
  Points x;                         ///< positions, 3 by (N + 1), mm
  Points xPrev;                     ///< positions one substep ago (velocity = (x − xPrev)/h)
  std::vector<std::uint8_t> alive;  ///< per link: 1 intact, 0 broken
  std::vector<Pierce> pierces;      ///< soft constraints through the tissue
  double time = 0.0;                ///< s
  double substep = 0.0;             ///< s: the last substep's length (x − xPrev spans it); 0 before any
  /// per link: s it has been held past knotBreakStretch by the thread pressing on itself, a knot
  /// drawn past tight (knot_strain.h); empty or 0 otherwise
  std::vector<double> heldPastBreak;

  /// The chain at rest, placed by `pose` (needle frame → world), at rest, nothing broken.
  static SutureState laidOut(const SutureModel& model,
                             const Eigen::Isometry3d& pose = Eigen::Isometry3d::Identity());
  int brokenLinkCount() const;
};

/// A run of nodes [first, last] joined by intact links: the whole chain, or one of the free
/// pieces a break leaves.
struct Piece {
  int first = 0;
  int last = 0;
};
/// The pieces of the chain in node order (links with alive[i] == 0 separate them).
std::vector<Piece> chainPieces(const std::vector<std::uint8_t>& alive);

/// Relative stretch of each link, (|x_{i+1} − x_i| − l_i)/l_i; broken links report 0.
std::vector<double> linkStretches(const SutureModel& model, const SutureState& state);
/// Largest |stretch| over the intact links.
double maxAbsStretch(const SutureModel& model, const Points& x,
                     const std::vector<std::uint8_t>& alive);

}  // namespace microsim::sim::suture
