#include "collision_fcl.h"

#if MICROSIM_HAVE_FCL
#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/AABB.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/collision.h>
#endif

#include <limits>
#include <stdexcept>

namespace microsim::bench {

#if MICROSIM_HAVE_FCL

namespace {

template <class Bv>
std::shared_ptr<fcl::BVHModel<Bv>> makeModel(const Eigen::Matrix3Xd& x,
                                             const std::vector<std::array<int, 3>>& triangles) {
  std::vector<fcl::Vector3d> points(x.cols());
  for (Eigen::Index i = 0; i < x.cols(); ++i) points[i] = x.col(i);
  std::vector<fcl::Triangle> tris;
  tris.reserve(triangles.size());
  for (const auto& t : triangles) tris.emplace_back(t[0], t[1], t[2]);
  auto model = std::make_shared<fcl::BVHModel<Bv>>();
  model->beginModel(static_cast<int>(tris.size()), static_cast<int>(points.size()));
  model->addSubModel(points, tris);
  model->endModel();
  return model;
}

template <class Bv>
void updateModel(fcl::BVHModel<Bv>& model, const Eigen::Matrix3Xd& x,
                 std::vector<fcl::Vector3d>& scratch) {
  scratch.resize(x.cols());
  for (Eigen::Index i = 0; i < x.cols(); ++i) scratch[i] = x.col(i);
  model.beginUpdateModel();
  model.updateSubModel(scratch);
  model.endUpdateModel(true, true);
}

}  // namespace

struct FclMesh::Impl {
  FclVolume volume;
  std::shared_ptr<fcl::BVHModel<fcl::OBBRSSd>> obbrss;
  std::shared_ptr<fcl::BVHModel<fcl::AABBd>> aabb;
  std::vector<fcl::Vector3d> scratch;
  const fcl::CollisionGeometryd* geometry() const {
    return volume == FclVolume::Obbrss ? static_cast<const fcl::CollisionGeometryd*>(obbrss.get())
                                       : static_cast<const fcl::CollisionGeometryd*>(aabb.get());
  }
};

bool fclAvailable() { return true; }

FclMesh::FclMesh(FclVolume volume, const Eigen::Matrix3Xd& x,
                 const std::vector<std::array<int, 3>>& triangles)
    : impl_(std::make_unique<Impl>()) {
  impl_->volume = volume;
  if (volume == FclVolume::Obbrss)
    impl_->obbrss = makeModel<fcl::OBBRSSd>(x, triangles);
  else
    impl_->aabb = makeModel<fcl::AABBd>(x, triangles);
}

FclMesh::~FclMesh() = default;

void FclMesh::update(const Eigen::Matrix3Xd& x) {
  if (impl_->volume == FclVolume::Obbrss)
    updateModel(*impl_->obbrss, x, impl_->scratch);
  else
    updateModel(*impl_->aabb, x, impl_->scratch);
}

std::size_t FclMesh::collide(const FclMesh& other, const Eigen::Vector3d& offset,
                             bool firstOnly) const {
  fcl::CollisionRequestd request(firstOnly ? 1 : std::numeric_limits<int>::max(), false);
  fcl::CollisionResultd result;
  fcl::Transform3d here = fcl::Transform3d::Identity();
  fcl::Transform3d there = fcl::Transform3d::Identity();
  there.translation() = offset;
  return fcl::collide(impl_->geometry(), here, other.impl_->geometry(), there, request, result);
}

#else

struct FclMesh::Impl {};

bool fclAvailable() { return false; }

FclMesh::FclMesh(FclVolume, const Eigen::Matrix3Xd&, const std::vector<std::array<int, 3>>&) {
  throw std::logic_error("microsim was configured without FCL");
}
FclMesh::~FclMesh() = default;
void FclMesh::update(const Eigen::Matrix3Xd&) {}
std::size_t FclMesh::collide(const FclMesh&, const Eigen::Vector3d&, bool) const { return 0; }

#endif

}  // namespace microsim::bench
