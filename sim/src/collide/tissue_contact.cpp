#include "microsim/sim/collide/tissue_contact.h"

#include "microsim/sim/collide/point_triangle.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace microsim::sim::collide {

namespace {

/// Links within which a face's corner makes it the node's own stretch of wall (tissue_contact.h).
/// Two were not enough: released after a pull to a stretch of 0.56, the shipped vessel's wall
/// snapped back onto faces three links along (a ring and a layer away), held there folded
/// 1.3 mm from rest; with three it springs back to rest in one solve.
constexpr int kOwnWallLinks = 3;

// a grid cell's key: 21 bits a coordinate, cells of ≥ 1 µm over ±1 m
std::int64_t packCell(const Eigen::Vector3i& c) {
  const auto b = [](int v) { return static_cast<std::int64_t>(v) & 0x1FFFFF; };
  return (b(c.x()) << 42) | (b(c.y()) << 21) | b(c.z());
}

// every node's faces
std::vector<std::vector<int>> facesOfNodes(const SpringModel& tissue) {
  std::vector<std::vector<int>> facesOf(static_cast<std::size_t>(tissue.nodeCount()));
  for (int f = 0; f < static_cast<int>(tissue.triangles().size()); ++f)
    for (int v : tissue.triangles()[static_cast<std::size_t>(f)])
      facesOf[static_cast<std::size_t>(v)].push_back(f);
  return facesOf;
}

// Appends to `near` the nodes at most kOwnWallLinks links from node i, by breadth-first
// layers, and marks them in `seen` (seen[j] == i: taken for i), i itself first.
void appendOwnWall(const SpringModel& tissue, int i, std::vector<int>& seen,
                   std::vector<int>& near) {
  near.push_back(i);
  seen[static_cast<std::size_t>(i)] = i;
  std::size_t from = near.size() - 1;
  for (int hop = 0; hop < kOwnWallLinks; ++hop) {
    const std::size_t to = near.size();
    for (std::size_t k = from; k < to; ++k)
      for (int li : tissue.linksOf(near[k])) {
        const int j = tissue.otherEnd(li, near[k]);
        if (seen[static_cast<std::size_t>(j)] == i) continue;
        seen[static_cast<std::size_t>(j)] = i;
        near.push_back(j);
      }
    from = to;
  }
}

// The nodes at rest, filed by cells of `distance` as sorted (cell, node), and the ones within
// `distance` of a node found in its cell and the 26 around it (none for a distance of 0).
class RestNeighbours {
 public:
  RestNeighbours(Points rest, double distance) : rest_(std::move(rest)), distance_(distance) {
    if (!(distance_ > 0.0)) return;
    for (int i = 0; i < static_cast<int>(rest_.cols()); ++i)
      cells_.emplace_back(packCell(cellOf(i)), i);
    std::sort(cells_.begin(), cells_.end());
  }

  // Appends to `near` the nodes within the distance of node i not yet marked in `seen` for
  // i, and marks them.
  void append(int i, std::vector<int>& seen, std::vector<int>& near) const {
    if (cells_.empty()) return;
    const Eigen::Vector3i c = cellOf(i);
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz)
          appendInCell(i, packCell(c + Eigen::Vector3i(dx, dy, dz)), seen, near);
  }

 private:
  Eigen::Vector3i cellOf(int i) const {
    return (rest_.col(i) / distance_).array().floor().cast<int>();
  }
  void appendInCell(int i, std::int64_t key, std::vector<int>& seen, std::vector<int>& near) const {
    const auto first =
        std::lower_bound(cells_.begin(), cells_.end(), std::pair<std::int64_t, int>(key, -1));
    for (auto it = first; it != cells_.end() && it->first == key; ++it) {
      const int j = it->second;
      if (seen[static_cast<std::size_t>(j)] == i) continue;
      if ((rest_.col(j) - rest_.col(i)).squaredNorm() >= distance_ * distance_) continue;
      seen[static_cast<std::size_t>(j)] = i;
      near.push_back(j);
    }
  }

  Points rest_;  // a copy: the model hands out a view of its positions
  double distance_;
  std::vector<std::pair<std::int64_t, int>> cells_;
};

}  // namespace

double defaultContactStiffness(const SpringModel& tissue) {
  double kMax = 0.0;
  for (const Link& link : tissue.links()) kMax = std::max(kMax, link.k);
  return 20.0 * kMax;
}

TissueContact::TissueContact(const SpringModel& tissue, const TissueContactParams& params)
    : tissue_(tissue), params_(params) {
  stiffness_ = params.stiffness > 0.0 ? params.stiffness : defaultContactStiffness(tissue);

  // the nodes on the surface, and the mean edge of its faces (the grid's cell)
  std::vector<std::uint8_t> onSurface(static_cast<std::size_t>(tissue.nodeCount()), 0);
  double edges = 0.0;
  const auto rest = tissue.restPositions();
  for (const auto& t : tissue.triangles())
    for (std::size_t c = 0; c < 3; ++c) {
      onSurface[static_cast<std::size_t>(t[c])] = 1;
      edges += (rest.col(t[c]) - rest.col(t[(c + 1) % 3])).norm();
    }
  for (int i = 0; i < tissue.nodeCount(); ++i)
    if (onSurface[static_cast<std::size_t>(i)]) surfaceNodes_.push_back(i);

  // the faces each surface node never meets: those with a corner on its own stretch of wall
  // or within selfDistance of it at rest
  const std::vector<std::vector<int>> facesOf = facesOfNodes(tissue);
  const RestNeighbours restNear(rest, params.selfDistance);
  ownFaces_.resize(static_cast<std::size_t>(tissue.nodeCount()));
  std::vector<int> seen(static_cast<std::size_t>(tissue.nodeCount()), -1);
  std::vector<int> faceSeen(tissue.triangles().size(), -1);
  std::vector<int> near;
  for (int i : surfaceNodes_) {
    near.clear();
    appendOwnWall(tissue, i, seen, near);
    restNear.append(i, seen, near);
    std::vector<int>& faces = ownFaces_[static_cast<std::size_t>(i)];
    for (int j : near)
      for (int f : facesOf[static_cast<std::size_t>(j)])
        if (faceSeen[static_cast<std::size_t>(f)] != i) {
          faceSeen[static_cast<std::size_t>(f)] = i;
          faces.push_back(f);
        }
    std::sort(faces.begin(), faces.end());
  }

  const double meanEdge = tissue.triangles().empty() ? 1.0 : edges / (3.0 * static_cast<double>(tissue.triangles().size()));
  cell_ = std::max({meanEdge, 2.0 * params.reach, 1e-6});
}

std::int64_t TissueContact::cellKey(int ix, int iy, int iz) const {
  return packCell(Eigen::Vector3i(ix, iy, iz));
}

void TissueContact::buildGrid(const Points& x) const {
  // the grid built last still serves while no node has moved half the slack from where it
  // was then (boxes were grown by reach + slack; see the header)
  const double slack = params_.reach;
  if (gridX_.cols() == x.cols()) {
    double moved2 = 0.0;
    for (Eigen::Index i = 0; i < x.cols() && moved2 <= 0.25 * slack * slack; ++i)
      moved2 = std::max(moved2, (x.col(i) - gridX_.col(i)).squaredNorm());
    if (moved2 <= 0.25 * slack * slack) return;
  }
  gridX_ = x;
  gridLeftFaceOut_ = false;
  const double r = params_.reach + slack;
  const auto& triangles = tissue_.triangles();
  const int faces = static_cast<int>(triangles.size());

  // every face's grown box in cells (left empty for a face left out), and the entries they make
  gridBoxes_.resize(2 * static_cast<std::size_t>(faces));
  std::size_t entries = 0;
  for (int f = 0; f < faces; ++f) {
    const auto& t = triangles[static_cast<std::size_t>(f)];
    Vec3 lo = x.col(t[0]).cwiseMin(x.col(t[1])).cwiseMin(x.col(t[2])).array() - r;
    Vec3 hi = x.col(t[0]).cwiseMax(x.col(t[1])).cwiseMax(x.col(t[2])).array() + r;
    Eigen::Vector3i& a = gridBoxes_[2 * static_cast<std::size_t>(f)];
    Eigen::Vector3i& b = gridBoxes_[2 * static_cast<std::size_t>(f) + 1];
    // a face torn far apart (or not finite) is left out rather than spread over the grid
    if (!lo.allFinite() || !hi.allFinite() || ((hi - lo).array() > 64.0 * cell_).any()) {
      gridLeftFaceOut_ = true;
      a.setOnes();
      b.setZero();
      continue;
    }
    a = (lo / cell_).array().floor().cast<int>();
    b = (hi / cell_).array().floor().cast<int>();
    entries += static_cast<std::size_t>((b - a + Eigen::Vector3i::Ones()).prod());
  }

  // filed by bucket, each bucket's entries in face order: a counting sort, two passes
  gridBits_ = 1;
  while ((std::size_t{1} << gridBits_) < entries) ++gridBits_;
  gridStart_.assign((std::size_t{1} << gridBits_) + 1, 0);
  const auto eachCell = [&](auto&& visit) {
    for (int f = 0; f < faces; ++f) {
      const Eigen::Vector3i& a = gridBoxes_[2 * static_cast<std::size_t>(f)];
      const Eigen::Vector3i& b = gridBoxes_[2 * static_cast<std::size_t>(f) + 1];
      for (int ix = a.x(); ix <= b.x(); ++ix)
        for (int iy = a.y(); iy <= b.y(); ++iy)
          for (int iz = a.z(); iz <= b.z(); ++iz) visit(cellKey(ix, iy, iz), f);
    }
  };
  eachCell([&](std::int64_t key, int) { ++gridStart_[gridBucket(key) + 1]; });
  for (std::size_t k = 1; k < gridStart_.size(); ++k) gridStart_[k] += gridStart_[k - 1];
  gridFill_.assign(gridStart_.begin(), gridStart_.end() - 1);
  grid_.resize(entries);
  eachCell([&](std::int64_t key, int f) {
    grid_[static_cast<std::size_t>(gridFill_[gridBucket(key)]++)] = {key, f};
  });
}

std::size_t TissueContact::gridBucket(std::int64_t key) const {
  // Fibonacci hashing: the top bits of the key times 2⁶⁴/φ
  return static_cast<std::size_t>((static_cast<std::uint64_t>(key) * 0x9E3779B97F4A7C15ULL) >>
                                  (64 - gridBits_));
}

std::pair<int, double> TissueContact::closestFace(const Points& x, int node, double radius,
                                                  double watch, double& nearest) const {
  const Vec3 p = x.col(node);
  if (!p.allFinite()) return {-1, 0.0};
  const std::vector<int>& own = ownFaces_[static_cast<std::size_t>(node)];
  const Eigen::Vector3i c = (p / cell_).array().floor().cast<int>();
  const std::int64_t key = cellKey(c.x(), c.y(), c.z());
  const std::size_t bucket = gridBucket(key);
  int best = -1;
  double bestScore = std::numeric_limits<double>::infinity();
  double bestSigned = 0.0;
  // the bucket's faces come in increasing order, as do the node's own: one walk along both
  auto ownAhead = own.begin();
  for (int e = gridStart_[bucket]; e < gridStart_[bucket + 1]; ++e) {
    const auto [cell, f] = grid_[static_cast<std::size_t>(e)];
    if (cell != key) continue;
    // a face whose box, grown by the radius, misses the node is farther than the radius
    // along one axis: most of a cell's faces (their boxes were grown by reach + slack) go
    // here, before the dearer eligibility and closest-point tests
    if ((p.array() < faceLow_.col(f).array() - watch).any() ||
        (p.array() > faceHigh_.col(f).array() + watch).any())
      continue;
    while (ownAhead != own.end() && *ownAhead < f) ++ownAhead;
    if (ownAhead != own.end() && *ownAhead == f) continue;
    const auto& t = tissue_.triangles()[static_cast<std::size_t>(f)];
    const PointTriangleClosest q = closestPointTriangle(p, x.col(t[0]), x.col(t[1]), x.col(t[2]));
    nearest = std::min(nearest, q.distance);
    if (!(q.distance < radius)) continue;
    const Vec3 normal = (x.col(t[1]) - x.col(t[0])).cross(x.col(t[2]) - x.col(t[0])).normalized();
    const double side = normal.dot(p - q.point);
    // at an edge or a corner several faces are equally near; the one the node faces (p − q
    // along its normal) is the one it would pass through, not the one it slides along
    const double facing = q.distance > 1e-12 ? std::abs(side) / q.distance : 1.0;
    const double score = q.distance * (2.0 - facing);
    if (!(score < bestScore)) continue;
    best = f;
    bestScore = score;
    bestSigned = side < 0.0 ? -q.distance : q.distance;
  }
  return {best, bestSigned};
}

bool TissueContact::stillClear(const Points& x) const {
  if (clearX_.cols() != x.cols() || x.cols() == 0) return false;
  const double quarter = 0.25 * params_.reach;
  // (a node that is not finite compares false and ends the skip)
  for (Eigen::Index i = 0; i < x.cols(); ++i)
    if (!((x.col(i) - clearX_.col(i)).squaredNorm() <= quarter * quarter)) return false;
  return true;
}

std::vector<TissueContactPair> TissueContact::pairsCloserThan(const Points& x, double signedDistance) const {
  std::vector<TissueContactPair> pairs;
  const auto& triangles = tissue_.triangles();
  if (triangles.empty() || stillClear(x)) return pairs;
  buildGrid(x);
  // every face's box at these positions, once for all the nodes that look at it
  faceLow_.resize(3, static_cast<Eigen::Index>(triangles.size()));
  faceHigh_.resize(3, static_cast<Eigen::Index>(triangles.size()));
  for (std::size_t f = 0; f < triangles.size(); ++f) {
    const auto& t = triangles[f];
    const auto column = static_cast<Eigen::Index>(f);
    faceLow_.col(column) = x.col(t[0]).cwiseMin(x.col(t[1])).cwiseMin(x.col(t[2]));
    faceHigh_.col(column) = x.col(t[0]).cwiseMax(x.col(t[1])).cwiseMax(x.col(t[2]));
  }
  // the grid holds every face within reach + slack/2 of a node (buildGrid): so far the
  // clearance is known exactly
  const double watch = 1.5 * params_.reach;
  double nearest = std::numeric_limits<double>::infinity();
  for (int i : surfaceNodes_) {
    const auto [face, distance] = closestFace(x, i, params_.reach, watch, nearest);
    if (face >= 0 && distance < signedDistance) pairs.push_back({i, face});
  }
  if (nearest >= watch && !gridLeftFaceOut_)
    clearX_ = x;
  else
    clearX_.resize(3, 0);
  return pairs;
}

std::vector<TissueContactPair> TissueContact::near(const Points& x) const {
  return pairsCloserThan(x, std::numeric_limits<double>::infinity());
}

std::vector<TissueContactPair> TissueContact::violations(const Points& x) const {
  return pairsCloserThan(x, 0.5 * params_.thickness);
}

PointSpring TissueContact::spring(const TissueContactPair& pair, const Points& x) const {
  const auto& t = tissue_.triangles()[static_cast<std::size_t>(pair.face)];
  const Vec3 p = x.col(pair.node);
  const PointTriangleClosest q = closestPointTriangle(p, x.col(t[0]), x.col(t[1]), x.col(t[2]));
  PointSpring s;
  s.nodes = {pair.node, t[0], t[1], t[2]};
  s.weights = {1.0, -q.barycentric.x(), -q.barycentric.y(), -q.barycentric.z()};
  Vec3 n = (x.col(t[1]) - x.col(t[0])).cross(x.col(t[2]) - x.col(t[0]));
  s.normal = n.norm() > 0.0 ? Vec3(n.normalized()) : Vec3::UnitZ();
  s.gap = params_.thickness;
  s.k = stiffness_;
  return s;
}

}  // namespace microsim::sim::collide
