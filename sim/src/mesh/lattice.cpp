#include "microsim/sim/mesh/lattice.h"

#include <cassert>

namespace microsim::sim {

namespace {

// two outward-wound triangles for the unit square with corners a, b, c, d (counter-
// clockwise seen from outside)
void addQuad(SpringModel& m, int a, int b, int c, int d) {
  m.addTriangle(a, b, c);
  m.addTriangle(a, c, d);
}

void addSurface(SpringModel& m, int n) {
  auto id = [n](int x, int y, int z) { return latticeIndex(n, x, y, z); };
  const int e = n - 1;
  for (int i = 0; i < e; ++i) {
    for (int j = 0; j < e; ++j) {
      // bottom (normal −z) and top (+z)
      addQuad(m, id(i, j, 0), id(i, j + 1, 0), id(i + 1, j + 1, 0), id(i + 1, j, 0));
      addQuad(m, id(i, j, e), id(i + 1, j, e), id(i + 1, j + 1, e), id(i, j + 1, e));
      // front (−y) and back (+y)
      addQuad(m, id(i, 0, j), id(i + 1, 0, j), id(i + 1, 0, j + 1), id(i, 0, j + 1));
      addQuad(m, id(i, e, j), id(i, e, j + 1), id(i + 1, e, j + 1), id(i + 1, e, j));
      // left (−x) and right (+x)
      addQuad(m, id(0, i, j), id(0, i, j + 1), id(0, i + 1, j + 1), id(0, i + 1, j));
      addQuad(m, id(e, i, j), id(e, i + 1, j), id(e, i + 1, j + 1), id(e, i, j + 1));
    }
  }
}

}  // namespace

SpringModel latticeBox(const LatticeDef& def) {
  assert(def.n >= 2);
  const int n = def.n;
  SpringModel m;
  auto id = [n](int x, int y, int z) { return latticeIndex(n, x, y, z); };

  // nodes in index order x fastest, z slowest
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) m.addNode(Vec3(x, y, z) * def.spacing, def.mass);

  // per node: axis links forward, then both diagonals of the face squares whose
  // lowest corner it is
  for (int z = 0; z < n; ++z) {
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) {
        const int i = id(x, y, z);
        if (x + 1 < n) m.addLink(i, id(x + 1, y, z), def.k);
        if (y + 1 < n) m.addLink(i, id(x, y + 1, z), def.k);
        if (z + 1 < n) m.addLink(i, id(x, y, z + 1), def.k);
        if (x + 1 < n && y + 1 < n) {
          m.addLink(i, id(x + 1, y + 1, z), def.k);
          m.addLink(id(x + 1, y, z), id(x, y + 1, z), def.k);
        }
        if (x + 1 < n && z + 1 < n) {
          m.addLink(i, id(x + 1, y, z + 1), def.k);
          m.addLink(id(x + 1, y, z), id(x, y, z + 1), def.k);
        }
        if (y + 1 < n && z + 1 < n) {
          m.addLink(i, id(x, y + 1, z + 1), def.k);
          m.addLink(id(x, y + 1, z), id(x, y, z + 1), def.k);
        }
      }
    }
  }

  if (def.fixBottom)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) m.setFixed(id(x, y, 0));

  addSurface(m, n);
  m.finalize();
  return m;
}

SpringModel latticeBox(int n, double k) {
  LatticeDef def;
  def.n = n;
  def.k = k;
  return latticeBox(def);
}

}  // namespace microsim::sim
