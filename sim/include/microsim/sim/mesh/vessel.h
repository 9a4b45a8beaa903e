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
// Wall material (WallMaterial, optional; without it the links and masses are the paper's
// lumped kLayer, kBetween, mass). With a material every link follows the exponential law
// (StiffnessLaw::Exponential, gain = b) with base stiffness k0 = E·A/L, L its rest length
// and A the cross-section of wall it stands for, thickness share × width share:
//   ring edge on a hull          A = (t/2)·a_r        each hull carries half the wall
//   axial edge on a hull         A = (t/2)·c_h        thickness t
//   radial spoke                 A = a_r·c̄           the node's patch of wall surface
//   diagonal of a quad face      A = h·Q/(8L)         shear links (see below)
// with a = length/(R − 1) the ring spacing, a_r its share at ring r (a, or a/2 at the two
// end rings), c_h = 2πρ_h/P the node spacing round hull h of radius ρ_h, c̄ their mean.
// The edges alone give the wall modulus E along the axis, round the ring and through the
// wall. A quad face of area Q between four nodes carries two diagonals: on a hull (the hull
// diagonals) h = t/2, Q = a·c_h; across the wall within a layer (the in-layer inner–outer
// crosses) h = a_r, Q = c̄·t; across the wall between layers (the crosses to the next
// ring) h = c̄, Q = a·t. Since the face's edges already carry its normal stiffness, its two
// diagonals share only a quarter of it, as shear links; a diagonal at angle θ to a pull
// still adds about cos⁴θ/4 of E to it. Measured on the default 7 × 16 vessel end
// (Vessel.TheWallNetworkHasAnAxialModulusNearTheMaterialsE): axial modulus ≈ 1.4·E. A lumped
// network is no continuum; this sits well inside the literature's spread (WallMaterial).
// Node mass = ρ·V/N, V = π(ρ_o² − ρ_i²)·length the wall's volume and N = 2·R·P the nodes.
// Node damping (dynamic solvers only) = 2ζ·√(m·K̄), K̄ = 2·Σk0/N the mean of Σk0 over a
// node's links: ζ = 1 damps a node's own small-strain oscillation critically.
// Explicit kLayer, kBetween, mass or damping (VesselDef::overrides) win over the derived
// values: links within a layer then have k0 = kLayer, links between layers k0 = kBetween,
// still with the material's law.
//
// Surface triangles, in this order, each wound so the normal points out of the wall
// material: outer hull (away from the axis), inner hull (into the lumen, towards the
// axis), clamped-end annulus (−direction), cut-end annulus (+direction).

#include "microsim/sim/mesh/spring_model.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace microsim::sim {

/// A vessel wall's material in the engine's units (mm, s, g; stress g/(mm·s²) = Pa).
/// Defaults are for a small (~1 mm) muscular artery, chosen inside literature ranges, not
/// fitted to one data set (a lumped spring network has no single "E" to fit anyway):
///   E   incremental modulus of arterial wall near zero to low load is of the order of
///       0.1–1 MPa, rising several-fold at high load (Bergel, J. Physiol. 156 (1961) 445–
///       457, dog arteries; Fung, "Biomechanics: Mechanical Properties of Living Tissues",
///       2nd ed. 1993, ch. 8). Constitutive fits put the soft matrix far lower and let
///       collagen carry the rest (Holzapfel, Gasser, Ogden, J. Elasticity 61 (2000) 1–48:
///       neo-Hookean c = 3 kPa for the media, exponential fibres), so 0.3 MPa stands for the
///       wall as handled, lightly loaded, not for elastin alone. 0.3 MPa = 3·10⁵ g/(mm·s²).
///   b   arterial wall stiffens tenfold and more from low load to near failure as collagen
///       is recruited; e^{b s} = 20 at s = 0.5 gives b = 6 (one-dimensional exponential
///       fits of soft tissue, Fung 1993 ch. 7–8, have exponents of this order).
///   ρ   soft tissue and blood: 1.06 g/cm³ = 1.06·10⁻³ g/mm³ (1.06 mg/mm³).
///   failure (not a material field; the scene's "tissue" limits): ultimate circumferential
///       stretch of human coronary artery layers ≈ 1.4–1.9 (Holzapfel, Sommer, Gasser,
///       Regitnig, Am. J. Physiol. Heart 289 (2005) H2048–H2058), a failure strain ≈ 0.4–0.9.
struct WallMaterial {
  double youngsModulus = 3.0e5;  ///< E, small-strain modulus (g/(mm·s²) = Pa): 0.3 MPa
  double fungExponent = 6.0;     ///< b, exponential stiffening (dimensionless), ≥ 0
  double density = 1.06e-3;      ///< ρ (g/mm³): 1.06 mg/mm³
  double dampingRatio = 1.0;     ///< ζ of a node's small-strain oscillation (dimensionless)
};

/// Which lumped fields of a VesselDef with a material still apply (given explicitly).
struct VesselOverrides {
  bool kLayer = false;
  bool kBetween = false;
  bool mass = false;
  bool damping = false;
};

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
  /// The wall's material; when set it derives stiffness, mass and damping (see above) in
  /// place of the four lumped fields above, except those `overrides` names.
  std::optional<WallMaterial> material;
  VesselOverrides overrides;
  bool clampFirstRing = true;      ///< fix both hulls of ring 0
  Vec3 origin = Vec3::Zero();      ///< centre of the clamped end ring (mm)
  Vec3 direction = Vec3::UnitX();  ///< axis from clamped to cut end (normalised on use)

  /// The paper's Fig. 2 vessel: 7 rings of 7 nodes per hull, 98 nodes, 581 links, the
  /// paper's lumped stiffness and masses (no material).
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
/// True when every field of the material is finite, E, ρ > 0 and b, ζ ≥ 0.
bool validWallMaterial(const WallMaterial& material);

}  // namespace microsim::sim
