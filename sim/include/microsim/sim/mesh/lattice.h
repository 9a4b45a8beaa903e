#pragma once
// The regular lattice box of Brown et al. 2002 §5 (Table 1, Fig. 5): the benchmark mesh
// every tissue solver is measured on.
//
// An n by n by n grid of nodes at unit spacing (1 mm), node (x, y, z) at index
// x + n·y + n²·z. Links join each node to its x, y and z neighbours and cross BOTH
// diagonals of every unit face square in the xy, xz and yz planes, all with the same
// stiffness k. Counting: 3·n²·(n − 1) axis links plus 6·n·(n − 1)² face diagonals, so
// 6³ → 1440, 8³ → 3696, 10³ → 7560, 15³ → 27,090 and 20³ → 66,120 links, the paper's
// figures. The bottom face (z = 0) is fixed; the paper's protocol then displaces the
// middle node of the top face (latticeTopMiddle) by one unit per cycle. (The paper also
// quotes 64 links for 3³; that one figure fits no rule that gives the five above: this
// rule gives 126.) Surface triangles cover the six faces, two per unit square, wound
// outward.

#include "microsim/sim/mesh/spring_model.h"

namespace microsim::sim {

struct LatticeDef {
  int n = 6;              ///< nodes per edge (≥ 2); the box is (n − 1) mm wide
  double k = 10.0;        ///< stiffness of every link (g/s²)
  double mass = 1.0;      ///< mass of every node (g)
  double spacing = 1.0;   ///< distance between neighbouring nodes (mm)
  bool fixBottom = true;  ///< fix every node of the z = 0 face
};

/// The lattice box described by `def`, finalized.
SpringModel latticeBox(const LatticeDef& def);
/// The paper's box: n³ nodes at unit spacing, stiffness k, bottom face fixed, finalized.
SpringModel latticeBox(int n, double k = 10.0);

/// Index of node (x, y, z) in an n³ lattice.
constexpr int latticeIndex(int n, int x, int y, int z) {
  return x + n * (y + n * z);
}
/// The middle node of the top face (z = n − 1), x = y = n / 2 (rounded down): the node
/// the paper displaces.
constexpr int latticeTopMiddle(int n) {
  return latticeIndex(n, n / 2, n / 2, n - 1);
}
/// Number of links of an n³ box: 3n²(n − 1) + 6n(n − 1)².
constexpr long long latticeLinkCount(long long n) {
  return 3 * n * n * (n - 1) + 6 * n * (n - 1) * (n - 1);
}

}  // namespace microsim::sim
