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

std::vector<int> pointsNearSegment(const Points& x, const Vec3& a, const Vec3& b, double radius,
                                   const std::vector<std::uint8_t>& skip) {
  std::vector<int> out;
  const Vec3 d = b - a;
  const double dd = d.squaredNorm();
  const double r2 = radius * radius;
  for (int i = 0; i < static_cast<int>(x.cols()); ++i) {
    if (!skip.empty() && skip[static_cast<std::size_t>(i)]) continue;
    const Vec3 p = x.col(i);
    const double t = dd > 0.0 ? std::clamp((p - a).dot(d) / dd, 0.0, 1.0) : 0.0;
    if ((p - (a + t * d)).squaredNorm() <= r2) out.push_back(i);
  }
  return out;
}

bool Forceps::update(const Eigen::Isometry3d& pose, double closure, bool& released) {
  const bool wasClosed = closed();
  pose_ = pose;
  closure_ = closure;
  released = wasClosed && !closed();
  return !wasClosed && closed();
}

void Forceps::holdTissue(const std::vector<int>& nodes, const Points& x) {
  nodes_ = nodes;
  offsets_.resize(3, static_cast<Eigen::Index>(nodes.size()));
  const Eigen::Isometry3d inverse = pose_.inverse();
  for (std::size_t k = 0; k < nodes.size(); ++k)
    offsets_.col(static_cast<Eigen::Index>(k)) = inverse * Vec3(x.col(nodes[k]));
}

void Forceps::holdSuture(int node, const Vec3& position, bool needle,
                         const Eigen::Matrix3d& needleRotation) {
  sutureNode_ = node;
  needle_ = needle;
  sutureOffset_ = pose_.inverse() * position;
  needleRelative_ = pose_.linear().transpose() * needleRotation;
}

void Forceps::release() {
  nodes_.clear();
  offsets_.resize(3, 0);
  sutureNode_ = -1;
  needle_ = false;
}

Points Forceps::heldTargets() const {
  Points out(3, offsets_.cols());
  for (Eigen::Index k = 0; k < offsets_.cols(); ++k) out.col(k) = pose_ * Vec3(offsets_.col(k));
  return out;
}

std::optional<suture::Grip> Forceps::grip() const {
  if (sutureNode_ < 0) return std::nullopt;
  suture::Grip g;
  g.node = sutureNode_;
  g.position = pose_ * sutureOffset_;
  g.oriented = needle_;
  g.rotation = pose_.linear() * needleRelative_;
  return g;
}

}  // namespace microsim::sim::tools
