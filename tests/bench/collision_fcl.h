#pragma once
// The peer of the collision benchmark: a triangle mesh in FCL (the Flexible Collision Library,
// Debian libfcl-dev), as a BVHModel refit after deformation. FCL types stay in
// collision_fcl.cpp; without FCL at configure time, fclAvailable() is false and the
// benchmark reports our figures without a peer.

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <memory>
#include <vector>

namespace microsim::bench {

bool fclAvailable();

enum class FclVolume { Obbrss, Aabb };

class FclMesh {
 public:
  /// Builds the BVH over the triangles at positions x (3 by #V).
  FclMesh(FclVolume volume, const Eigen::Matrix3Xd& x,
          const std::vector<std::array<int, 3>>& triangles);
  ~FclMesh();
  FclMesh(const FclMesh&) = delete;
  FclMesh& operator=(const FclMesh&) = delete;

  /// FCL's deformation path: beginUpdateModel, updateSubModel(all vertices),
  /// endUpdateModel(refit = true, bottom-up = true).
  void update(const Eigen::Matrix3Xd& x);
  /// Colliding triangle pairs with `other` translated by `offset` (mm): the first only, or
  /// all of them (num_max_contacts unbounded, no contact details).
  std::size_t collide(const FclMesh& other, const Eigen::Vector3d& offset, bool firstOnly) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace microsim::bench
