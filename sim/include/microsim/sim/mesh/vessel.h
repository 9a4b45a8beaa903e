#pragma once
// The double-hulled vessel of Brown et al. 2002 §3.3.3 (Fig. 2): a severed blood vessel
// as two coaxial cylinders of nodes, the outer one the adventitial surface and the inner
// one the lumen, so that the gap between them is the wall.
//
// Each hull is `rings` evenly spaced layers along the axis, each layer `nodesPerRing`
// nodes evenly spaced on a circle; inner node j of a ring sits radially under outer
// node j. Links (for R rings, P nodes per ring):
//   within a layer (k = kLayer, the paper's 50):
//     ring edges on each hull                               2·R·P
//     inner–outer radial spokes                               R·P
//     inner–outer crosses to the next node round the ring   2·R·P
//   between adjacent layers (k = kBetween, the paper's 100):
//     axial edges on each hull                          2·(R − 1)·P
//     both diagonals of each hull quad                  4·(R − 1)·P
//     inner–outer crosses to the next ring              2·(R − 1)·P
// The inner–outer links carry the shear that keeps the wall from twisting about its
// axis (the paper's "torsional stability"). Total 5·R·P + 8·(R − 1)·P; the default
// R = P = 7 gives 98 nodes and 245 + 336 = 581 links, the paper's Fig. 2 count exactly.
//
// The first ring (both hulls) is clamped (fixed), the last ring is the cut end the
// trainee sutures. The axis runs from `origin` (clamped end) along `direction`;
// node j of a ring sits at angle 2πj/P measured from a reference vector normal to
// the axis (the projection of +z, or of +x when the axis is along z).
//
// Surface triangles, in this order, each wound so the normal points out of the wall
// material: outer hull (away from the axis), inner hull (into the lumen, towards the
// axis), clamped-end annulus (−direction), cut-end annulus (+direction).

#include "microsim/sim/mesh/spring_model.h"

#include <cstdint>
#include <vector>

namespace microsim::sim {

struct VesselDef {
  double radius = 0.5;             ///< outer radius (mm): a ~1 mm vessel
  double wallThickness = 0.1;      ///< outer minus inner radius (mm), 0 < t < radius
  double length = 3.0;             ///< clamped end to cut end along the axis (mm)
  int rings = 7;                   ///< layers along the axis per hull (≥ 2)
  int nodesPerRing = 7;            ///< nodes around each ring (≥ 3)
  double kLayer = 50.0;            ///< stiffness of links within a layer (g/s²)
  double kBetween = 100.0;         ///< stiffness of links between adjacent layers (g/s²)
  double mass = 1.0;               ///< mass of every node (g)
  double damping = 0.0;            ///< damping of every node (g/s)
  bool clampFirstRing = true;      ///< fix both hulls of ring 0
  Vec3 origin = Vec3::Zero();      ///< centre of the clamped end ring (mm)
  Vec3 direction = Vec3::UnitX();  ///< axis from clamped to cut end (normalised on use)

  /// The paper's Fig. 2 vessel: 7 rings of 7 nodes per hull, 98 nodes, 581 links.
  static VesselDef paper() { return {}; }
  /// A fine vessel of the same geometry: 71 rings of 70 nodes per hull, 9940 nodes,
  /// 64,050 links, node spacing ≈ 0.045 mm on the outer hull both ways.
  static VesselDef fine() {
    VesselDef d;
    d.rings = 71;
    d.nodesPerRing = 70;
    return d;
  }
};

enum class VesselHull : std::uint8_t { Inner, Outer };

/// A half-open range [begin, end) of indices into SpringModel::triangles().
struct TriangleRange {
  int begin = 0;
  int end = 0;
  int size() const { return end - begin; }
};

/// The vessel's model plus what later stages need to know about each node (pierce
/// metrics, the cut edge) and where each surface's triangles are.
struct VesselMesh {
  SpringModel model;
  VesselDef def;
  std::vector<int> ring;         ///< per node: layer index, 0 at the clamped end
  std::vector<int> sector;       ///< per node: index j around the ring, angle 2πj/P
  std::vector<VesselHull> hull;  ///< per node: inner or outer cylinder
  TriangleRange outerSurface;    ///< adventitia, normals away from the axis
  TriangleRange innerSurface;    ///< lumen, normals towards the axis
  TriangleRange clampedEnd;      ///< annulus at ring 0
  TriangleRange cutEnd;          ///< annulus at ring R − 1

  /// Index of the node on `hull`, layer `ring`, sector `sector` (taken modulo P).
  int node(VesselHull h, int ringIndex, int sectorIndex) const;
  /// Nodes of the cut end (last ring, both hulls), outer then inner, by sector.
  std::vector<int> cutEdgeNodes() const;
};

/// Number of links vessel(def) makes: 5·R·P + 8·(R − 1)·P.
constexpr long long vesselLinkCount(int rings, int nodesPerRing) {
  return 5LL * rings * nodesPerRing + 8LL * (rings - 1) * nodesPerRing;
}

/// The vessel described by `def`, finalized. `def` must be valid (see validVesselDef).
VesselMesh vessel(const VesselDef& def = VesselDef::paper());
/// True when every field is in range and finite.
bool validVesselDef(const VesselDef& def);

}  // namespace microsim::sim
