#pragma once
// A flat triangle grid: the paper's collision workload (§5.4: the 100 by 100 grid of
// 20,000 triangles deformed by local bumps, and the 8 by 8 plane of 8192 triangles).
//
// (cellsX + 1)·(cellsY + 1) nodes in the z = 0 plane, centred on the origin, node (i, j)
// at index i + (cellsX + 1)·j and position ((i − cellsX/2)·size, (j − cellsY/2)·size, 0).
// Each square cell is split along its (i, j)–(i + 1, j + 1) diagonal into two triangles
// wound counter-clockwise seen from +z (normal +z): 2·cellsX·cellsY triangles. Links are
// the unique triangle edges, 3·cellsX·cellsY + cellsX + cellsY of them, all stiffness k.

#include "microsim/sim/mesh/spring_model.h"

namespace microsim::sim {

struct GridDef {
  int cellsX = 100;        ///< cells along x (≥ 1)
  int cellsY = 100;        ///< cells along y (≥ 1)
  double size = 1.0;       ///< edge length of one square cell (mm)
  double k = 10.0;         ///< stiffness of every link (g/s²)
  double mass = 1.0;       ///< mass of every node (g)
  bool fixBorder = false;  ///< fix the nodes on the grid's outline
};

/// The grid described by `def`, finalized.
SpringModel gridMesh(const GridDef& def);
/// A cellsX by cellsY grid of square cells `size` mm wide, stiffness 10, nothing fixed:
/// gridMesh(100, 100, 1.0) has 20,000 triangles, gridMesh(64, 64, 0.125) is the paper's
/// 8 by 8 plane of 8192 triangles.
SpringModel gridMesh(int cellsX, int cellsY, double size);

/// Index of node (i, j) of a grid with `cellsX` cells along x.
constexpr int gridIndex(int cellsX, int i, int j) {
  return i + (cellsX + 1) * j;
}

}  // namespace microsim::sim
