#include "microsim/sim/mesh/vessel.h"

#include <Eigen/Geometry>

#include <cassert>
#include <cmath>
#include <numbers>

namespace microsim::sim {

namespace {

bool finite(const Vec3& v) {
  return v.allFinite();
}

/// One link of the generator before its stiffness is known: the wall it stands for.
struct VesselLinkSpec {
  int a = 0;
  int b = 0;
  bool layer = true;  ///< within a layer (kLayer) or between adjacent layers (kBetween)
  double area = 0.0;  ///< an edge's cross-section A (mm²)
  double face = 0.0;  ///< a diagonal's thickness share × shared face area, h·Q (mm³)
};

}  // namespace

bool validWallMaterial(const WallMaterial& m) {
  return std::isfinite(m.youngsModulus) && std::isfinite(m.fungExponent) &&
         std::isfinite(m.density) && std::isfinite(m.dampingRatio) && m.youngsModulus > 0.0 &&
         m.fungExponent >= 0.0 && m.density > 0.0 && m.dampingRatio >= 0.0;
}

bool validVesselDef(const VesselDef& d) {
  return std::isfinite(d.radius) && std::isfinite(d.wallThickness) && std::isfinite(d.length) &&
         std::isfinite(d.kLayer) && std::isfinite(d.kBetween) && std::isfinite(d.mass) &&
         std::isfinite(d.damping) && finite(d.origin) && finite(d.direction) && d.radius > 0.0 &&
         d.wallThickness > 0.0 && d.wallThickness < d.radius && d.length > 0.0 && d.rings >= 2 &&
         d.nodesPerRing >= 3 && d.kLayer >= 0.0 && d.kBetween >= 0.0 && d.mass > 0.0 &&
         d.damping >= 0.0 && d.direction.norm() > 0.0 &&
         (!d.material || validWallMaterial(*d.material));
}

int VesselMesh::node(VesselHull h, int ringIndex, int sectorIndex) const {
  const int p = def.nodesPerRing;
  const int j = ((sectorIndex % p) + p) % p;
  return (ringIndex * 2 + static_cast<int>(h)) * p + j;
}

std::vector<int> VesselMesh::cutEdgeNodes() const {
  std::vector<int> out;
  for (VesselHull h : {VesselHull::Outer, VesselHull::Inner})
    for (int j = 0; j < def.nodesPerRing; ++j) out.push_back(node(h, def.rings - 1, j));
  return out;
}

VesselMesh vessel(const VesselDef& def) {
  assert(validVesselDef(def));
  VesselMesh v;
  v.def = def;
  const int rings = def.rings;
  const int p = def.nodesPerRing;
  SpringModel& m = v.model;

  // orthonormal frame (e1, e2, axis) with e1 the projection of +z (or +x) normal to the axis
  const Vec3 axis = def.direction.normalized();
  const Vec3 ref = std::abs(axis.z()) < 0.9 ? Vec3::UnitZ() : Vec3::UnitX();
  const Vec3 e1 = (ref - ref.dot(axis) * axis).normalized();
  const Vec3 e2 = axis.cross(e1);
  const double inner = def.radius - def.wallThickness;

  // node positions ring by ring, inner hull then outer, sector by sector
  std::vector<Vec3> position;
  for (int r = 0; r < rings; ++r) {
    const Vec3 centre = def.origin + axis * (def.length * r / (rings - 1));
    for (VesselHull h : {VesselHull::Inner, VesselHull::Outer}) {
      const double radius = h == VesselHull::Inner ? inner : def.radius;
      for (int j = 0; j < p; ++j) {
        const double theta = 2.0 * std::numbers::pi * j / p;
        position.push_back(centre + radius * (std::cos(theta) * e1 + std::sin(theta) * e2));
        v.ring.push_back(r);
        v.sector.push_back(j);
        v.hull.push_back(h);
      }
    }
  }

  // the links with the wall they stand for, thickness share × width share (mm²), and
  // for a diagonal the area of the face it shares with its twin
  const double t = def.wallThickness;
  const double a = def.length / (rings - 1);
  const double cMean = std::numbers::pi * (def.radius + inner) / p;
  auto axialShare = [&](int r) { return r == 0 || r + 1 == rings ? 0.5 * a : a; };
  auto hullSpacing = [&](VesselHull h) {
    return 2.0 * std::numbers::pi * (h == VesselHull::Inner ? inner : def.radius) / p;
  };
  std::vector<VesselLinkSpec> links;
  auto in = [&](int r, int j) { return v.node(VesselHull::Inner, r, j); };
  auto out = [&](int r, int j) { return v.node(VesselHull::Outer, r, j); };
  auto edge = [&](int i, int j, bool layer, double area) {
    links.push_back({i, j, layer, area, 0.0});
  };
  auto diagonal = [&](int i, int j, bool layer, double thickness, double face) {
    links.push_back({i, j, layer, 0.0, thickness * face});
  };
  for (int r = 0; r < rings; ++r) {
    // within the layer: ring edges, spokes, inner–outer crosses
    const double ar = axialShare(r);
    for (int j = 0; j < p; ++j) {
      edge(out(r, j), out(r, j + 1), true, 0.5 * t * ar);
      edge(in(r, j), in(r, j + 1), true, 0.5 * t * ar);
      edge(in(r, j), out(r, j), true, ar * cMean);
      diagonal(in(r, j), out(r, j + 1), true, ar, cMean * t);
      diagonal(out(r, j), in(r, j + 1), true, ar, cMean * t);
    }
    if (r + 1 == rings) break;
    // to the next layer: axial edges, both quad diagonals on each hull, inner–outer crosses
    for (int j = 0; j < p; ++j) {
      for (VesselHull h : {VesselHull::Outer, VesselHull::Inner}) {
        const double ch = hullSpacing(h);
        edge(v.node(h, r, j), v.node(h, r + 1, j), false, 0.5 * t * ch);
        diagonal(v.node(h, r, j), v.node(h, r + 1, j + 1), false, 0.5 * t, a * ch);
        diagonal(v.node(h, r, j + 1), v.node(h, r + 1, j), false, 0.5 * t, a * ch);
      }
      diagonal(in(r, j), out(r + 1, j), false, cMean, a * t);
      diagonal(out(r, j), in(r + 1, j), false, cMean, a * t);
    }
  }

  // stiffness, law, mass and damping: the paper's lumped values or the material's
  const int nodes = static_cast<int>(position.size());
  const WallMaterial* material = def.material ? &*def.material : nullptr;
  const StiffnessLaw law = material ? StiffnessLaw::Exponential : StiffnessLaw::Constant;
  const double gain = material ? material->fungExponent : 0.0;
  std::vector<double> k(links.size());
  double kSum = 0.0;
  for (std::size_t i = 0; i < links.size(); ++i) {
    const VesselLinkSpec& l = links[i];
    const bool lumped = !material || (l.layer ? def.overrides.kLayer : def.overrides.kBetween);
    const double rest = (position[static_cast<std::size_t>(l.b)] - position[static_cast<std::size_t>(l.a)]).norm();
    // k0 = E·A/L, a diagonal's A = h·Q/(8L)
    const double area = l.face > 0.0 ? l.face / (8.0 * rest) : l.area;
    k[i] = lumped ? (l.layer ? def.kLayer : def.kBetween) : material->youngsModulus * area / rest;
    kSum += k[i];
  }
  const double wallVolume = std::numbers::pi * (def.radius * def.radius - inner * inner) * def.length;
  const double mass = material && !def.overrides.mass ? material->density * wallVolume / nodes : def.mass;
  const double damping = material && !def.overrides.damping
                             ? 2.0 * material->dampingRatio * std::sqrt(mass * 2.0 * kSum / nodes)
                             : def.damping;
  for (const Vec3& x : position) m.addNode(x, mass, damping);
  for (std::size_t i = 0; i < links.size(); ++i)
    m.addLink(links[i].a, links[i].b, k[i], -1.0, law, gain);

  if (def.clampFirstRing)
    for (VesselHull h : {VesselHull::Inner, VesselHull::Outer})
      for (int j = 0; j < p; ++j) m.setFixed(v.node(h, 0, j));

  // outer hull wound outward, inner hull wound into the lumen
  auto quad = [&m](int a, int b, int c, int d) {
    m.addTriangle(a, b, c);
    m.addTriangle(a, c, d);
  };
  auto count = [&m] { return static_cast<int>(m.triangles().size()); };
  v.outerSurface.begin = count();
  for (int r = 0; r + 1 < rings; ++r)
    for (int j = 0; j < p; ++j) quad(out(r, j), out(r, j + 1), out(r + 1, j + 1), out(r + 1, j));
  v.outerSurface.end = v.innerSurface.begin = count();
  for (int r = 0; r + 1 < rings; ++r)
    for (int j = 0; j < p; ++j) quad(in(r, j), in(r + 1, j), in(r + 1, j + 1), in(r, j + 1));
  v.innerSurface.end = count();

  // end annuli: the clamped end faces −axis, the cut end +axis
  v.clampedEnd.begin = count();
  for (int j = 0; j < p; ++j) quad(out(0, j), in(0, j), in(0, j + 1), out(0, j + 1));
  v.clampedEnd.end = v.cutEnd.begin = count();
  const int last = rings - 1;
  for (int j = 0; j < p; ++j) quad(out(last, j), out(last, j + 1), in(last, j + 1), in(last, j));
  v.cutEnd.end = count();

  m.finalize();
  return v;
}

}  // namespace microsim::sim
