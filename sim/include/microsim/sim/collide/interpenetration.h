#pragma once
// Which tissue nodes lie inside another body: the check behind "nothing interpenetrates"
// (issue 17) and the scene benchmark's `interpenetrating pairs`.
//
// A body is a set of consecutive nodes with a closed triangle shell around its material,
// e.g. one vessel end: its outer hull, inner hull, clamped-end and cut-end annuli together
// bound the wall (mesh/vessel.h), a closed surface of genus one. A node p of body A lies
// inside body B (A ≠ B) when B's generalised winding number at p is above one half:
//
//   w_B(p) = (1 / 4π) Σ_{t ∈ shell(B)} Ω_t(p),
//   Ω_t(p) = 2 atan2(a·(b × c), |a||b||c| + (a·b)|c| + (a·c)|b| + (b·c)|a|),
//
// a, b, c the corners of triangle t minus p (Van Oosterom & Strackee 1983, the solid angle
// of a triangle). For a closed shell w is 1 inside the material (−1 for a shell wound
// inwards) and 0 outside, whatever the shell's shape; only |w| is compared, so the
// winding order does not matter. A node on the shell gives ½ and does not count: "inside"
// is strict. A node's own body is never tested. Nodes outside B's bounding box (of its
// current node positions) are skipped without a sum.
//
// Cost: O(nodes of the other bodies inside B's box × triangles of B's shell).
// Units: millimetres.

#include "microsim/sim/mesh/spring_model.h"
#include "microsim/sim/mesh/vessel.h"

#include <vector>

namespace microsim::sim {
struct SceneVessel;
}

namespace microsim::sim::collide {

/// A closed body of the tissue: nodes [firstNode, firstNode + nodeCount) and the triangle
/// ranges (into SpringModel::triangles()) that together form its closed shell.
struct ClosedBody {
  int firstNode = 0;
  int nodeCount = 0;
  std::vector<TriangleRange> shell;
};

/// One node inside a body it does not belong to.
struct PenetratingNode {
  int node = -1;  ///< tissue node
  int body = -1;  ///< index of the body it lies inside
};

struct Interpenetration {
  int count = 0;  ///< pairs (node, other body) with the node strictly inside the body
  std::vector<PenetratingNode> pairs;  ///< by body, then by node
};

/// One body per scene vessel (each end of a severed vessel is one), in the same order:
/// 2·rings·nodesPerRing nodes from firstNode, shell = outer, inner, clamped and cut surfaces.
std::vector<ClosedBody> vesselBodies(const std::vector<SceneVessel>& vessels);

/// The generalised winding number of the body's shell at p (positions x: 3 by #N, mm).
double windingNumber(const SpringModel& model, const Points& x, const ClosedBody& body, const Vec3& p);

/// Every pair (node of one body, another body) with the node strictly inside that body.
Interpenetration interpenetration(const SpringModel& model, const Points& x,
                                  const std::vector<ClosedBody>& bodies);
/// The same for a scene's vessels (vesselBodies).
Interpenetration interpenetration(const SpringModel& model, const Points& x,
                                  const std::vector<SceneVessel>& vessels);

}  // namespace microsim::sim::collide
