#pragma once
// The mass–spring tissue model of Brown et al. 2002 (§3.3), split MuJoCo-style into a
// constant model (topology, rest lengths, stiffness, masses) and a state (positions,
// velocities) that solvers advance: solve(const SpringModel&, SpringState&, ...).
//
// Units: millimetres, seconds, grams. Force is then g·mm/s² (1 µN) and stiffness
// g/s² (force per millimetre of stretch).
//
// Spring force on node a from link (a, b):  F = k(s) (l − r) u,  u = (x_b − x_a)/l,
// l = |x_b − x_a|, r = rest length, s = (l − r)/r the strain. The stiffness is either
// constant, k(s) = k0, or stiffening in tension, the usual shape of vessel wall (collagen
// recruitment): polynomial, k(s) = k0 (1 + gain·max(s, 0)²), or exponential (Fung-type),
// tension T = k0 r (e^{b s} − 1)/b for s > 0 with b = gain, so that dT/dl = k0 e^{b s}
// (spring_kernels.h has the equations and the overflow guard).
//
// Cutting removes links without rebuilding anything: a removed link stays in `links`
// and in the adjacency, marked dead, and every kernel skips it. Indices stay valid, so
// node orderings, trees and recordings that name links survive a cut.

#include "microsim/sim/mesh/point_spring.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace microsim::sim {

using Vec3 = Eigen::Vector3d;
/// Node positions or velocities: 3 by #N, column i is node i (mm or mm/s).
using Points = Eigen::Matrix3Xd;

enum class StiffnessLaw : std::uint8_t {
  Constant,    ///< k(s) = k0
  Stiffening,  ///< k(s) = k0 (1 + gain·max(s, 0)²)
  Exponential, ///< T = k0 r (e^{gain·s} − 1)/gain for s > 0, k0 (l − r) for s ≤ 0 (Fung-type)
};

struct Link {
  int a = 0;
  int b = 0;
  double rest = 0.0;       ///< rest length (mm), ≥ 0
  double k = 0.0;          ///< base stiffness k0 (g/s²), ≥ 0
  double gain = 0.0;       ///< stiffening gain (dimensionless): Stiffening's gain, Exponential's b
  StiffnessLaw law = StiffnessLaw::Constant;
  bool alive = true;       ///< false once cut
};

/// A node's role: free nodes are solved for; fixed nodes never move (clamps, bone);
/// control nodes follow a tool (their targets arrive in SpringControls each step).
enum class NodeRole : std::uint8_t { Free, Fixed };

class SpringModel {
 public:
  /// Adds a node at `position` (mm) with `mass` (g) and `damping` (g/s); returns its index.
  int addNode(const Vec3& position, double mass = 1.0, double damping = 0.0);
  /// Adds a link; rest < 0 means "the current distance between the rest positions".
  int addLink(int a, int b, double k, double rest = -1.0,
              StiffnessLaw law = StiffnessLaw::Constant, double gain = 0.0);
  void addTriangle(int a, int b, int c) { triangles_.push_back({a, b, c}); }
  void setFixed(int node, bool fixed = true);

  /// Marks a link dead (cutting). Idempotent. Returns false for an unknown index.
  bool removeLink(int link);

  /// Builds the node→link adjacency. Called once after the last addNode/addLink;
  /// kernels that use adjacency assert it is current.
  void finalize();
  bool finalized() const { return finalized_; }

  int nodeCount() const { return static_cast<int>(mass_.size()); }
  int linkCount() const { return static_cast<int>(links_.size()); }
  int aliveLinkCount() const { return aliveLinks_; }

  /// Rest positions, 3 by nodeCount() (mm). A view: bind it with `const auto`, since
  /// binding it to `const Points&` would copy the whole matrix.
  auto restPositions() const { return rest_.leftCols(nodeCount()); }
  double mass(int i) const { return mass_[i]; }
  double damping(int i) const { return damping_[i]; }
  const std::vector<double>& masses() const { return mass_; }
  const std::vector<double>& dampings() const { return damping_; }
  bool isFixed(int i) const { return role_[i] == NodeRole::Fixed; }
  const std::vector<NodeRole>& roles() const { return role_; }
  std::vector<int> fixedNodes() const;

  const std::vector<Link>& links() const { return links_; }
  const Link& link(int i) const { return links_[i]; }
  const std::vector<std::array<int, 3>>& triangles() const { return triangles_; }

  /// Links incident to node i (dead ones included; check Link::alive).
  std::span<const int> linksOf(int i) const {
    return {adjacency_.data() + adjacencyStart_[i],
            static_cast<std::size_t>(adjacencyStart_[i + 1] - adjacencyStart_[i])};
  }
  /// The node at the other end of `link` from `node`.
  int otherEnd(int link, int node) const {
    const Link& l = links_[link];
    return l.a == node ? l.b : l.a;
  }

  /// Gravity (mm/s²); zero unless a scene asks for it (the paper's figures have it off).
  Vec3 gravity = Vec3::Zero();

 private:
  // rest positions with spare columns past nodeCount(): addNode grows the capacity
  // geometrically, so building an n-node mesh costs O(n), not O(n²) copies
  Points rest_{3, 0};
  std::vector<double> mass_;
  std::vector<double> damping_;
  std::vector<NodeRole> role_;
  std::vector<Link> links_;
  std::vector<std::array<int, 3>> triangles_;
  std::vector<int> adjacencyStart_{0};
  std::vector<int> adjacency_;
  int aliveLinks_ = 0;
  bool finalized_ = false;
};

/// What a solver advances. x and v are 3 by #N.
struct SpringState {
  Points x;
  Points v;

  /// The state at rest: x = rest positions, v = 0.
  static SpringState atRest(const SpringModel& model);
};

/// What acts on the tissue this step besides its links: positions imposed on control nodes
/// (the nodes a tool holds), and soft terms (point_spring.h: the thread's pull at a pierce,
/// contacts). Soft terms are honoured by the solvers whose supportsPointSprings() is true.
struct SpringControls {
  std::vector<int> nodes;
  Points targets{3, 0};  ///< 3 by nodes.size(), mm
  std::vector<PointSpring> springs;

  void add(int node, const Vec3& target);
  int size() const { return static_cast<int>(nodes.size()); }
};

}  // namespace microsim::sim
