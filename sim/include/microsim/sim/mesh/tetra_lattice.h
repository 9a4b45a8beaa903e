#pragma once
// A tetrahedral lattice like the paper's cutting mesh (Brown et al. 2002 Fig. 3a:
// 40,889 nodes, 212,206 links): a block of unit cubes, each split into five tetrahedra,
// with a link along every tetrahedron edge.
//
// Nodes form an nx by ny by nz grid at `spacing`, node (x, y, z) at index
// x + nx·(y + ny·z). The five-tetrahedron split alternates with the parity of the cube
// so that neighbouring cubes agree on the diagonal of their shared face: in every unit
// face square the diagonal joins the two corners whose x + y + z is even. A cube whose
// lowest corner is even holds the central tetrahedron (000, 110, 101, 011) and the four
// corner tetrahedra cut off at 100, 010, 001 and 111; an odd cube is its mirror image.
// Links: axis edges plus one diagonal per face square, no body diagonals:
//   (nx−1)·ny·nz + nx·(ny−1)·nz + nx·ny·(nz−1)                       axis
//   (nx−1)(ny−1)·nz + (nx−1)·ny·(nz−1) + nx·(ny−1)(nz−1)             face diagonals
// The paper's count is matched by a 4-layer slab: the default 146 by 70 by 4 has 40,880
// nodes and 212,248 links (paper: 40,889 and 212,206; its exact shape is not given).
// Surface triangles: every boundary face square split along its diagonal, wound outward.

#include "microsim/sim/mesh/spring_model.h"

#include <array>
#include <vector>

namespace microsim::sim {

struct TetraLatticeDef {
  int nx = 146;           ///< nodes along x (≥ 2)
  int ny = 70;            ///< nodes along y (≥ 2)
  int nz = 4;             ///< nodes along z (≥ 2)
  double spacing = 1.0;   ///< edge of one cube (mm)
  double k = 10.0;        ///< stiffness of every link (g/s²)
  double mass = 1.0;      ///< mass of every node (g)
  bool fixBottom = true;  ///< fix every node of the z = 0 face
};

struct TetraMesh {
  SpringModel model;
  /// Each tetrahedron's four node indices, positively oriented ((b−a)×(c−a)·(d−a) > 0).
  std::vector<std::array<int, 4>> tetrahedra;
};

/// The lattice described by `def`, finalized.
TetraMesh tetraLattice(const TetraLatticeDef& def = {});

/// Links tetraLattice makes for an nx by ny by nz block.
constexpr long long tetraLatticeLinkCount(long long nx, long long ny, long long nz) {
  return (nx - 1) * ny * nz + nx * (ny - 1) * nz + nx * ny * (nz - 1) + (nx - 1) * (ny - 1) * nz +
         (nx - 1) * ny * (nz - 1) + nx * (ny - 1) * (nz - 1);
}

}  // namespace microsim::sim
