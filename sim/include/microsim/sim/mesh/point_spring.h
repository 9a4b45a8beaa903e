#pragma once
// A soft term on the tissue that is not one of its links: a zero-rest spring between a point
// of the tissue and an anchor, or a one-sided (contact) spring that only pushes.
//
// The point is a weighted sum of up to four nodes, g = Σ_k c_k x_k (mm). The weights say
// what the point is:
//   a point of a face        c = (u, v, w) barycentric, anchor = where it is pulled to
//                            (a thread through a pierce, a jaw holding the wall);
//   a node against a face    c = (1, −u, −v, −w), anchor = 0: g is the node's offset from
//                            the face point, so both sides move (tissue against tissue);
//   a node against a tool    c = (1), anchor = the tool's surface point.
// Energy (nJ), with d = g − anchor:
//   two-sided (normal = 0)   E = ½ k |d|²
//   one-sided (|normal| = 1) E = ½ k min(n·d − gap, 0)²     (pushes along n until n·d ≥ gap)
// The force on node x_k is −c_k ∂E/∂g, and the Hessian block of nodes (a, b) is
// c_a c_b k I (two-sided) or c_a c_b k n nᵀ (one-sided, while pressed; 0 otherwise). The
// normal is frozen for the solve, so a contact is a linearised constraint that the scene
// re-detects between solves (scene_contact.h). Every term is convex in x.
//
// Units: mm, k in g/s² (force per mm), forces in µN.

#include <Eigen/Core>

#include <algorithm>
#include <array>

namespace microsim::sim {

struct PointSpring {
  std::array<int, 4> nodes{-1, -1, -1, -1};  ///< −1 ends the list
  std::array<double, 4> weights{0.0, 0.0, 0.0, 0.0};
  Eigen::Vector3d anchor = Eigen::Vector3d::Zero();  ///< mm
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  ///< zero: two-sided; unit: one-sided
  double gap = 0.0;  ///< mm, one-sided only: the separation it keeps
  double k = 0.0;    ///< g/s²

  bool oneSided() const { return normal.squaredNorm() > 0.0; }
  int size() const {
    int n = 0;
    while (n < 4 && nodes[static_cast<std::size_t>(n)] >= 0) ++n;
    return n;
  }
};

/// g − anchor of `s` at positions `x` (3 by #N, mm).
template <class Positions>
Eigen::Vector3d pointSpringOffset(const PointSpring& s, const Positions& x) {
  Eigen::Vector3d g = -s.anchor;
  for (int k = 0; k < s.size(); ++k)
    g += s.weights[static_cast<std::size_t>(k)] * x.col(s.nodes[static_cast<std::size_t>(k)]);
  return g;
}

/// −∂E/∂g (µN): the force on the point; node k gets c_k times it.
inline Eigen::Vector3d pointSpringForce(const PointSpring& s, const Eigen::Vector3d& d) {
  if (!s.oneSided()) return -s.k * d;
  const double depth = s.normal.dot(d) - s.gap;
  return depth < 0.0 ? Eigen::Vector3d(-s.k * depth * s.normal) : Eigen::Vector3d::Zero();
}

/// E (nJ).
inline double pointSpringEnergy(const PointSpring& s, const Eigen::Vector3d& d) {
  if (!s.oneSided()) return 0.5 * s.k * d.squaredNorm();
  const double depth = std::min(s.normal.dot(d) - s.gap, 0.0);
  return 0.5 * s.k * depth * depth;
}

/// ∂²E/∂g² (3 by 3, g/s²); the block of nodes (a, b) is c_a c_b times it.
inline Eigen::Matrix3d pointSpringHessian(const PointSpring& s, const Eigen::Vector3d& d) {
  if (!s.oneSided()) return s.k * Eigen::Matrix3d::Identity();
  if (s.normal.dot(d) - s.gap < 0.0) return s.k * (s.normal * s.normal.transpose());
  return Eigen::Matrix3d::Zero();
}

}  // namespace microsim::sim
