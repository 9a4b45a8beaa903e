#include "microsim/sim/mesh/smooth_surface.h"

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

namespace microsim::sim {

namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;

using RowMajor = Eigen::SparseMatrix<double, Eigen::RowMajor>;
using ColumnMajor = Eigen::SparseMatrix<double>;

struct SmoothSurface::Weights {
  std::vector<int> nodes;  ///< the surface's coarse nodes, in control-point order
  /// Each level's vertices from the level before (a handful of weights each), then the
  /// finest level's limit positions from it, applied in turn: three times fewer products than
  /// their composite (dozens of weights a vertex at three levels), which is never formed.
  std::vector<RowMajor> steps;
  /// The composite's rows of the refined vertices on the nodes, factorised: the control
  /// points whose limit surface passes through the nodes solve it.
  Eigen::SparseLU<ColumnMajor> through;
  // scratch of `place`
  mutable Eigen::MatrixX3d nodePoints;
  mutable Eigen::MatrixX3d controls;
  mutable std::vector<std::vector<double>>
      levels;  ///< each level's values, the control points' first

  /// `width` values per control point in levels[0] carried through every step: the last of
  /// `levels` (the refined vertices), `width` values per vertex.
  const std::vector<double>& refine(std::size_t width) const;
  /// The refined vertices' limit positions for the nodes in `nodePoints`, 3 values per vertex.
  const std::vector<double>& placeNodes() const;
};

namespace {

// One step of the refinement: each row of `step` a weighted sum of `from`'s points, `width`
// values per point.
void refineStep(const RowMajor& step, std::size_t width, const std::vector<double>& from,
                std::vector<double>& to) {
  to.assign(width * static_cast<std::size_t>(step.rows()), 0.0);
  const int* begin = step.outerIndexPtr();
  const int* column = step.innerIndexPtr();
  const double* weight = step.valuePtr();
  for (Eigen::Index row = 0; row < step.rows(); ++row) {
    double* out = &to[width * static_cast<std::size_t>(row)];
    for (int k = begin[row]; k < begin[row + 1]; ++k) {
      const double* p = &from[width * static_cast<std::size_t>(column[k])];
      for (std::size_t c = 0; c < width; ++c) out[c] += weight[k] * p[c];
    }
  }
}

// The same for points (x, y, z), every frame: each weight scales a point's three coordinates
// together, kept in registers (Eigen's sparse-dense product walks the weights once per
// coordinate; a loop over a width, even a fixed one, took two thirds more instructions).
void refinePoints(const RowMajor& step, const std::vector<double>& from, std::vector<double>& to) {
  to.resize(3 * static_cast<std::size_t>(step.rows()));
  const int* begin = step.outerIndexPtr();
  const int* column = step.innerIndexPtr();
  const double* weight = step.valuePtr();
  for (Eigen::Index row = 0; row < step.rows(); ++row) {
    double x = 0.0, y = 0.0, z = 0.0;
    for (int k = begin[row]; k < begin[row + 1]; ++k) {
      const double* p = &from[3 * static_cast<std::size_t>(column[k])];
      x += weight[k] * p[0];
      y += weight[k] * p[1];
      z += weight[k] * p[2];
    }
    double* out = &to[3 * static_cast<std::size_t>(row)];
    out[0] = x;
    out[1] = y;
    out[2] = z;
  }
}

}  // namespace

const std::vector<double>& SmoothSurface::Weights::refine(std::size_t width) const {
  levels.resize(steps.size() + 1);  // a buffer a level: sized once
  for (std::size_t k = 0; k < steps.size(); ++k) {
    if (width == 3)
      refinePoints(steps[k], levels[k], levels[k + 1]);
    else
      refineStep(steps[k], width, levels[k], levels[k + 1]);
  }
  return levels.back();
}

const std::vector<double>& SmoothSurface::Weights::placeNodes() const {
  controls = through.solve(nodePoints);
  levels.resize(steps.size() + 1);
  levels[0].resize(3 * static_cast<std::size_t>(controls.rows()));
  for (Eigen::Index p = 0; p < controls.rows(); ++p)
    for (Eigen::Index c = 0; c < 3; ++c)
      levels[0][static_cast<std::size_t>(3 * p + c)] = controls(p, c);
  return refine(3);
}

namespace {

// A vertex of one level as a weighted sum of the points of the level before (or, for the limit,
// of its own level), built up by OpenSubdiv's PrimvarRefiner from unit impulses (it asks only
// for Clear and AddWithWeight). A Loop mask holds a vertex and its ring, a handful of points,
// so a flat list searched linearly beats any map.
struct Stencil {
  std::vector<std::pair<int, double>> terms;

  void Clear(void* /*unused*/ = nullptr) { terms.clear(); }
  void AddWithWeight(const Stencil& src, double weight) {
    for (const auto& term : src.terms) {
      const int point =
          term.first;  // a plain variable: clang 14 cannot capture a structured binding
      const auto same = std::find_if(terms.begin(), terms.end(),
                                     [point](const auto& t) { return t.first == point; });
      if (same == terms.end())
        terms.emplace_back(point, term.second * weight);
      else
        same->second += term.second * weight;
    }
  }
};

// OpenSubdiv reports topology errors through a global callback that prints by default; the
// engine never prints (the caller learns of the failure from build's result).
void quietOpenSubdiv() {
  Far::SetErrorCallback([](Far::ErrorType, const char*) {});
  Far::SetWarningCallback([](const char*) {});
}

// Edges whose two faces meet at more than kCreaseAngleDeg at rest, as pairs of control points.
std::vector<int> creaseEdges(const std::vector<std::array<int, 3>>& faces, const Points& points) {
  std::map<std::pair<int, int>, std::vector<int>> edgeFaces;
  std::vector<Vec3> normals(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const auto& t = faces[f];
    const Vec3 n = (points.col(t[1]) - points.col(t[0])).cross(points.col(t[2]) - points.col(t[0]));
    normals[f] = n.norm() > 0.0 ? Vec3(n.normalized()) : Vec3::Zero();
    for (std::size_t k = 0; k < 3; ++k) {
      const int a = t[k];
      const int b = t[(k + 1) % 3];
      edgeFaces[{std::min(a, b), std::max(a, b)}].push_back(static_cast<int>(f));
    }
  }
  const double sharp = std::cos(kCreaseAngleDeg * std::numbers::pi / 180.0);
  std::vector<int> pairs;
  for (const auto& [edge, around] : edgeFaces) {
    if (around.size() != 2) continue;  // a border or a non-manifold edge: OpenSubdiv keeps it sharp
    const Vec3& n0 = normals[static_cast<std::size_t>(around[0])];
    const Vec3& n1 = normals[static_cast<std::size_t>(around[1])];
    if (n0.isZero() || n1.isZero() || n0.dot(n1) >= sharp) continue;
    pairs.push_back(edge.first);
    pairs.push_back(edge.second);
  }
  return pairs;
}

}  // namespace

SmoothSurface::SmoothSurface() : weights_(std::make_unique<Weights>()) {}
SmoothSurface::SmoothSurface(SmoothSurface&&) noexcept = default;
SmoothSurface& SmoothSurface::operator=(SmoothSurface&&) noexcept = default;
SmoothSurface::~SmoothSurface() = default;

int SmoothSurface::vertexCount() const {
  return weights_->steps.empty() ? 0 : static_cast<int>(weights_->steps.back().rows());
}

std::optional<SmoothSurface> SmoothSurface::build(const std::vector<std::array<int, 3>>& triangles,
                                                  const Points& rest, int levels,
                                                  SmoothSurfaceError* error) {
  const auto failed = [error](SmoothSurfaceError why) {
    if (error) *error = why;
    return std::optional<SmoothSurface>();
  };
  if (triangles.empty()) return failed(SmoothSurfaceError::NoTriangles);
  if (levels < 1 || levels > kMaxSmoothLevels) return failed(SmoothSurfaceError::BadLevels);

  // the nodes on some triangle become the control points, in node order
  const auto nodeCount = static_cast<int>(rest.cols());
  SmoothSurface s;
  s.nodeVertex_.assign(static_cast<std::size_t>(nodeCount), -1);
  std::vector<int> control(static_cast<std::size_t>(nodeCount), -1);
  for (const auto& t : triangles)
    for (int n : t) {
      if (n < 0 || n >= nodeCount) return failed(SmoothSurfaceError::BadTopology);
      control[static_cast<std::size_t>(n)] = 0;
    }
  for (int n = 0; n < nodeCount; ++n)
    if (control[static_cast<std::size_t>(n)] == 0) {
      control[static_cast<std::size_t>(n)] = static_cast<int>(s.weights_->nodes.size());
      s.weights_->nodes.push_back(n);
    }
  const auto points = static_cast<int>(s.weights_->nodes.size());
  std::vector<std::array<int, 3>> faces(triangles.size());
  Points controlRest(3, points);
  for (int p = 0; p < points; ++p)
    controlRest.col(p) = rest.col(s.weights_->nodes[static_cast<std::size_t>(p)]);
  for (std::size_t f = 0; f < triangles.size(); ++f)
    for (std::size_t k = 0; k < 3; ++k)
      faces[f][k] = control[static_cast<std::size_t>(triangles[f][k])];

  const std::vector<int> creases = creaseEdges(faces, controlRest);
  const std::vector<float> sharpness(creases.size() / 2, Sdc::Crease::SHARPNESS_INFINITE);
  const std::vector<int> corners(faces.size(), 3);
  Far::TopologyDescriptor desc;
  desc.numVertices = points;
  desc.numFaces = static_cast<int>(faces.size());
  desc.numVertsPerFace = corners.data();
  desc.vertIndicesPerFace = faces.front().data();
  desc.numCreases = static_cast<int>(sharpness.size());
  desc.creaseVertexIndexPairs = creases.data();
  desc.creaseWeights = sharpness.data();

  Sdc::Options rules;
  rules.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
  quietOpenSubdiv();
  std::unique_ptr<Far::TopologyRefiner> refiner(
      Far::TopologyRefinerFactory<Far::TopologyDescriptor>::Create(
          desc,
          Far::TopologyRefinerFactory<Far::TopologyDescriptor>::Options(Sdc::SCHEME_LOOP, rules)));
  if (!refiner) return failed(SmoothSurfaceError::BadTopology);
  Far::TopologyRefiner::UniformOptions uniform(levels);
  uniform.fullTopologyInLastLevel = true;  // the limit needs every vertex's ring
  refiner->RefineUniform(uniform);

  // each level's vertices as weights of the level before, then the limit of the finest
  const Far::PrimvarRefinerReal<double> primvars(*refiner);
  const auto impulses = [](int count) {
    std::vector<Stencil> one(static_cast<std::size_t>(count));
    for (int p = 0; p < count; ++p) one[static_cast<std::size_t>(p)].terms = {{p, 1.0}};
    return one;
  };
  const auto matrix = [](const std::vector<Stencil>& rows, int columns) {
    std::vector<Eigen::Triplet<double>> terms;
    for (std::size_t v = 0; v < rows.size(); ++v)
      for (const auto& [point, w] : rows[v].terms)
        terms.emplace_back(static_cast<int>(v), point, w);
    RowMajor m(static_cast<Eigen::Index>(rows.size()), columns);
    m.setFromTriplets(terms.begin(), terms.end());
    return m;
  };
  std::vector<int> parentsCoarser(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f) parentsCoarser[f] = static_cast<int>(f);
  for (int level = 1; level <= levels; ++level) {
    const int coarserCount = refiner->GetLevel(level - 1).GetNumVertices();
    std::vector<Stencil> finer(static_cast<std::size_t>(refiner->GetLevel(level).GetNumVertices()));
    primvars.Interpolate(level, impulses(coarserCount), finer);
    s.weights_->steps.push_back(matrix(finer, coarserCount));
    std::vector<int> parentsFiner(static_cast<std::size_t>(refiner->GetLevel(level).GetNumFaces()));
    primvars.InterpolateFaceUniform(level, parentsCoarser, parentsFiner);
    parentsCoarser = std::move(parentsFiner);
  }
  const int finestCount = refiner->GetLevel(levels).GetNumVertices();
  std::vector<Stencil> limit(static_cast<std::size_t>(finestCount));
  primvars.Limit(impulses(finestCount), limit);
  s.weights_->steps.push_back(matrix(limit, finestCount));

  const Far::TopologyLevel& finest = refiner->GetLevel(levels);
  s.triangles_.resize(static_cast<std::size_t>(finest.GetNumFaces()));
  for (int f = 0; f < finest.GetNumFaces(); ++f) {
    const Far::ConstIndexArray corner = finest.GetFaceVertices(f);
    s.triangles_[static_cast<std::size_t>(f)] = {corner[0], corner[1], corner[2]};
  }
  s.parent_ = std::move(parentsCoarser);

  // the refined vertex on each node, and the nodes' rows of the composite (carried back
  // through the levels from the finest): the surface must pass through them
  std::vector<Eigen::Triplet<double>> onNodes;
  for (int p = 0; p < points; ++p) {
    int v = p;
    for (int level = 0; level < levels; ++level)
      v = refiner->GetLevel(level).GetVertexChildVertex(v);
    s.nodeVertex_[static_cast<std::size_t>(s.weights_->nodes[static_cast<std::size_t>(p)])] = v;
    onNodes.emplace_back(p, v, 1.0);
  }
  RowMajor rows(points, finestCount);
  rows.setFromTriplets(onNodes.begin(), onNodes.end());
  for (auto step = s.weights_->steps.rbegin(); step != s.weights_->steps.rend(); ++step)
    rows = RowMajor(rows * *step);
  s.weights_->through.compute(ColumnMajor(rows));
  if (s.weights_->through.info() != Eigen::Success)
    return failed(SmoothSurfaceError::SingularLimits);

  if (error) *error = SmoothSurfaceError::None;
  return s;
}

void SmoothSurface::place(const float* nodes, std::vector<float>& out) const {
  Weights& w = *weights_;
  w.nodePoints.resize(static_cast<Eigen::Index>(w.nodes.size()), 3);
  for (std::size_t p = 0; p < w.nodes.size(); ++p)
    for (std::size_t c = 0; c < 3; ++c)
      w.nodePoints(static_cast<Eigen::Index>(p), static_cast<Eigen::Index>(c)) =
          nodes[3 * static_cast<std::size_t>(w.nodes[p]) + c];
  const std::vector<double>& placed = w.placeNodes();
  out.resize(placed.size());
  std::transform(placed.begin(), placed.end(), out.begin(),
                 [](double x) { return static_cast<float>(x); });
}

void SmoothSurface::place(const Points& nodes, Points& out) const {
  Weights& w = *weights_;
  w.nodePoints.resize(static_cast<Eigen::Index>(w.nodes.size()), 3);
  for (std::size_t p = 0; p < w.nodes.size(); ++p)
    w.nodePoints.row(static_cast<Eigen::Index>(p)) = nodes.col(w.nodes[p]).transpose();
  const std::vector<double>& placed = w.placeNodes();
  out = Eigen::Map<const Points>(placed.data(), 3, static_cast<Eigen::Index>(placed.size() / 3));
}

void SmoothSurface::blend(const std::vector<float>& perNode, int channels,
                          std::vector<float>& out) const {
  const Weights& w = *weights_;
  const auto width = static_cast<std::size_t>(std::max(channels, 1));
  w.levels.resize(w.steps.size() + 1);
  w.levels[0].resize(width * w.nodes.size());
  for (std::size_t p = 0; p < w.nodes.size(); ++p)
    for (std::size_t c = 0; c < width; ++c)
      w.levels[0][p * width + c] = perNode[static_cast<std::size_t>(w.nodes[p]) * width + c];
  const std::vector<double>& blended = w.refine(width);
  out.resize(blended.size());
  std::transform(blended.begin(), blended.end(), out.begin(),
                 [](double x) { return static_cast<float>(x); });
}

}  // namespace microsim::sim
