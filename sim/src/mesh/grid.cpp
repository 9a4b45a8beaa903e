#include "microsim/sim/mesh/grid.h"

#include <cassert>

namespace microsim::sim {

SpringModel gridMesh(const GridDef& def) {
  assert(def.cellsX >= 1 && def.cellsY >= 1 && def.size > 0.0);
  const int cx = def.cellsX;
  const int cy = def.cellsY;
  auto id = [cx](int i, int j) { return gridIndex(cx, i, j); };
  SpringModel m;

  // nodes row by row, centred on the origin
  for (int j = 0; j <= cy; ++j)
    for (int i = 0; i <= cx; ++i)
      m.addNode(Vec3((i - 0.5 * cx) * def.size, (j - 0.5 * cy) * def.size, 0.0), def.mass);

  // per node: the edges to +x, +y and the cell diagonal
  for (int j = 0; j <= cy; ++j) {
    for (int i = 0; i <= cx; ++i) {
      if (i < cx) m.addLink(id(i, j), id(i + 1, j), def.k);
      if (j < cy) m.addLink(id(i, j), id(i, j + 1), def.k);
      if (i < cx && j < cy) m.addLink(id(i, j), id(i + 1, j + 1), def.k);
    }
  }

  // two triangles per cell, normal +z
  for (int j = 0; j < cy; ++j) {
    for (int i = 0; i < cx; ++i) {
      m.addTriangle(id(i, j), id(i + 1, j), id(i + 1, j + 1));
      m.addTriangle(id(i, j), id(i + 1, j + 1), id(i, j + 1));
    }
  }

  if (def.fixBorder)
    for (int j = 0; j <= cy; ++j)
      for (int i = 0; i <= cx; ++i)
        if (i == 0 || j == 0 || i == cx || j == cy) m.setFixed(id(i, j));

  m.finalize();
  return m;
}

SpringModel gridMesh(int cellsX, int cellsY, double size) {
  GridDef def;
  def.cellsX = cellsX;
  def.cellsY = cellsY;
  def.size = size;
  return gridMesh(def);
}

}  // namespace microsim::sim
