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

}  // namespace

bool validVesselDef(const VesselDef& d) {
  return std::isfinite(d.radius) && std::isfinite(d.wallThickness) && std::isfinite(d.length) &&
         std::isfinite(d.kLayer) && std::isfinite(d.kBetween) && std::isfinite(d.mass) &&
         std::isfinite(d.damping) && finite(d.origin) && finite(d.direction) && d.radius > 0.0 &&
         d.wallThickness > 0.0 && d.wallThickness < d.radius && d.length > 0.0 && d.rings >= 2 &&
         d.nodesPerRing >= 3 && d.kLayer >= 0.0 && d.kBetween >= 0.0 && d.mass > 0.0 &&
         d.damping >= 0.0 && d.direction.norm() > 0.0;
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

  // nodes ring by ring, inner hull then outer, sector by sector
  for (int r = 0; r < rings; ++r) {
    const Vec3 centre = def.origin + axis * (def.length * r / (rings - 1));
    for (VesselHull h : {VesselHull::Inner, VesselHull::Outer}) {
      const double radius = h == VesselHull::Inner ? inner : def.radius;
      for (int j = 0; j < p; ++j) {
        const double theta = 2.0 * std::numbers::pi * j / p;
        m.addNode(centre + radius * (std::cos(theta) * e1 + std::sin(theta) * e2), def.mass,
                  def.damping);
        v.ring.push_back(r);
        v.sector.push_back(j);
        v.hull.push_back(h);
      }
    }
  }

  auto in = [&](int r, int j) { return v.node(VesselHull::Inner, r, j); };
  auto out = [&](int r, int j) { return v.node(VesselHull::Outer, r, j); };
  for (int r = 0; r < rings; ++r) {
    // within the layer: ring edges, spokes, inner–outer crosses
    for (int j = 0; j < p; ++j) {
      m.addLink(out(r, j), out(r, j + 1), def.kLayer);
      m.addLink(in(r, j), in(r, j + 1), def.kLayer);
      m.addLink(in(r, j), out(r, j), def.kLayer);
      m.addLink(in(r, j), out(r, j + 1), def.kLayer);
      m.addLink(out(r, j), in(r, j + 1), def.kLayer);
    }
    if (r + 1 == rings) break;
    // to the next layer: axial edges, both quad diagonals on each hull, inner–outer crosses
    for (int j = 0; j < p; ++j) {
      for (VesselHull h : {VesselHull::Outer, VesselHull::Inner}) {
        m.addLink(v.node(h, r, j), v.node(h, r + 1, j), def.kBetween);
        m.addLink(v.node(h, r, j), v.node(h, r + 1, j + 1), def.kBetween);
        m.addLink(v.node(h, r, j + 1), v.node(h, r + 1, j), def.kBetween);
      }
      m.addLink(in(r, j), out(r + 1, j), def.kBetween);
      m.addLink(out(r, j), in(r + 1, j), def.kBetween);
    }
  }

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
