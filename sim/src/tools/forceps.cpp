#include "microsim/sim/tools/forceps.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace microsim::sim::tools {

double jawLength(const ForcepsDef& def) {
  return def.jawVertices.cols() > 0 ? std::max(def.jawVertices.row(0).maxCoeff(), 0.0) : 0.0;
}

double jawAngle(const ForcepsDef& def, double closure) {
  return (1.0 - std::clamp(closure, 0.0, 1.0)) * def.openingDeg * std::numbers::pi / 180.0;
}

std::array<Eigen::Isometry3d, 2> jawPoses(const ForcepsDef& def, const Eigen::Isometry3d& pose,
                                          double closure) {
  const double theta = jawAngle(def, closure);
  const Vec3 hinge(jawLength(def), 0.0, 0.0);
  std::array<Eigen::Isometry3d, 2> out;
  for (int j = 0; j < 2; ++j) {
    // turn about the hinge; the lower jaw is the mirror image
    Eigen::Isometry3d jaw = Eigen::Isometry3d::Identity();
    jaw.translate(hinge);
    jaw.rotate(Eigen::AngleAxisd(j == 0 ? -theta : theta, Vec3::UnitZ()));
    jaw.translate(-hinge);
    if (j == 1) jaw.linear() = jaw.linear() * Eigen::Vector3d(1.0, -1.0, 1.0).asDiagonal();
    out[static_cast<std::size_t>(j)] = pose * jaw;
  }
  return out;
}

std::array<Vec3, 2> jawTips(const ForcepsDef& def, const Eigen::Isometry3d& pose, double closure) {
  const auto jaws = jawPoses(def, pose, closure);
  return {jaws[0] * Vec3::Zero(), jaws[1] * Vec3::Zero()};
}

Points jawVertices(const ForcepsDef& def, const Eigen::Isometry3d& pose, double closure) {
  const auto jaws = jawPoses(def, pose, closure);
  const Eigen::Index n = def.jawVertices.cols();
  Points out(3, 2 * n);
  for (int j = 0; j < 2; ++j)
    for (Eigen::Index i = 0; i < n; ++i)
      out.col(j * n + i) = jaws[static_cast<std::size_t>(j)] * Vec3(def.jawVertices.col(i));
  return out;
}

std::vector<std::array<int, 3>> jawTriangles(const ForcepsDef& def) {
  const int n = static_cast<int>(def.jawVertices.cols());
  std::vector<std::array<int, 3>> out = def.jawTriangles;
  for (const auto& t : def.jawTriangles) out.push_back({t[0] + n, t[2] + n, t[1] + n});
  return out;
}

bool Forceps::update(const Eigen::Isometry3d& pose, double closure, double dt, bool& released) {
  const bool wasClosed = closed();
  closedFrom_ = closure_;
  pose_ = pose;
  // the hold goes the moment the hand eases its squeeze; the jaws themselves part no faster
  // than their spring opens them
  squeeze_ = closure;
  const double slowest = def_.openingSeconds > 0.0 ? closure_ - dt / def_.openingSeconds : closure;
  closure_ = std::max(closure, slowest);
  released = wasClosed && !closed();
  return !wasClosed && closed();
}

void Forceps::holdTissue(const std::vector<FaceGrasp>& faces, const SpringModel& tissue, const Points& x) {
  const Eigen::Isometry3d inverse = pose_.inverse();

  // each face's point kept where it is in the tool frame, its share of the stiffness by area
  double area = 0.0;
  for (const FaceGrasp& g : faces) area += g.area;
  faces_.clear();
  for (const FaceGrasp& g : faces) {
    HeldFacePoint p;
    p.face = g.face;
    p.corners = tissue.triangles()[static_cast<std::size_t>(g.face)];
    p.barycentric = g.barycentric;
    Vec3 point = Vec3::Zero();
    for (std::size_t c = 0; c < 3; ++c) point += g.barycentric[static_cast<Eigen::Index>(c)] * x.col(p.corners[c]);
    p.offset = inverse * point;
    p.share = area > 0.0 ? g.area / area : 1.0 / static_cast<double>(faces.size());
    faces_.push_back(p);
  }

  // their free corners, for solvers that hold nodes
  nodes_.clear();
  for (const HeldFacePoint& p : faces_)
    for (int n : p.corners)
      if (!tissue.isFixed(n)) nodes_.push_back(n);
  std::sort(nodes_.begin(), nodes_.end());
  nodes_.erase(std::unique(nodes_.begin(), nodes_.end()), nodes_.end());
  offsets_.resize(3, static_cast<Eigen::Index>(nodes_.size()));
  for (std::size_t k = 0; k < nodes_.size(); ++k)
    offsets_.col(static_cast<Eigen::Index>(k)) = inverse * Vec3(x.col(nodes_[k]));
}

void Forceps::holdSuture(const ChainGrasp& at, const suture::SutureModel& model, const Points& x) {
  // a point within rounding of a node is the node
  const double length = (x.col(at.link + 1) - x.col(at.link)).norm();
  suture::Grip where;
  where.node = at.link;
  where.fraction = at.fraction;
  if (at.fraction * length <= kGripSnap) {
    where.fraction = 0.0;
  } else if ((1.0 - at.fraction) * length <= kGripSnap) {
    where.node = at.link + 1;
    where.fraction = 0.0;
  }

  // the point, the needle's rotation and the held link's direction, kept in the tool frame
  sutureNode_ = where.node;
  sutureFraction_ = where.fraction;
  needle_ = suture::gripHoldsNeedle(model, where);
  sutureOffset_ = pose_.inverse() * suture::gripPoint(x, where);
  needleRelative_ = pose_.linear().transpose() * suture::needleRotation(model, x);
  const Vec3 link = where.fraction > 0.0 ? Vec3(x.col(where.node + 1) - x.col(where.node)) : Vec3::Zero();
  linkDirection_ = link.norm() > 0.0 ? Vec3(pose_.linear().transpose() * link.normalized()) : Vec3::Zero();
}

void Forceps::release() {
  faces_.clear();
  nodes_.clear();
  offsets_.resize(3, 0);
  sutureNode_ = -1;
  sutureFraction_ = 0.0;
  needle_ = false;
}

Points Forceps::heldTargets() const {
  Points out(3, offsets_.cols());
  for (Eigen::Index k = 0; k < offsets_.cols(); ++k) out.col(k) = pose_ * Vec3(offsets_.col(k));
  return out;
}

void Forceps::appendHoldSprings(std::vector<PointSpring>& out) const {
  for (const HeldFacePoint& p : faces_) {
    PointSpring spring;
    for (std::size_t c = 0; c < 3; ++c) {
      spring.nodes[c] = p.corners[c];
      spring.weights[c] = p.barycentric[static_cast<Eigen::Index>(c)];
    }
    spring.anchor = pose_ * p.offset;
    spring.k = def_.holdStiffness * p.share;
    out.push_back(spring);
  }
}

std::optional<suture::Grip> Forceps::grip() const {
  if (sutureNode_ < 0) return std::nullopt;
  suture::Grip g;
  g.node = sutureNode_;
  g.fraction = sutureFraction_;
  g.position = pose_ * sutureOffset_;
  g.oriented = needle_;
  g.rotation = pose_.linear() * needleRelative_;
  if (sutureFraction_ > 0.0 && !needle_) g.direction = pose_.linear() * linkDirection_;
  return g;
}

}  // namespace microsim::sim::tools
