#include "microsim/sim/mesh/tetra_lattice.h"

#include <Eigen/Geometry>

#include <cassert>
#include <utility>

namespace microsim::sim {

namespace {

struct Block {
  int nx, ny, nz;
  int id(int x, int y, int z) const { return x + nx * (y + ny * z); }
  static bool even(int x, int y, int z) { return (x + y + z) % 2 == 0; }
};

// the face square spanned from corner o along axes u and v: the diagonal joining its
// two even corners
std::pair<int, int> faceDiagonal(const Block& b, const std::array<int, 3>& o,
                                 const std::array<int, 3>& u, const std::array<int, 3>& v) {
  const std::array<int, 3> pu{o[0] + u[0], o[1] + u[1], o[2] + u[2]};
  const std::array<int, 3> pv{o[0] + v[0], o[1] + v[1], o[2] + v[2]};
  const std::array<int, 3> pw{pu[0] + v[0], pu[1] + v[1], pu[2] + v[2]};
  if (Block::even(o[0], o[1], o[2])) return {b.id(o[0], o[1], o[2]), b.id(pw[0], pw[1], pw[2])};
  return {b.id(pu[0], pu[1], pu[2]), b.id(pv[0], pv[1], pv[2])};
}

// two triangles for a boundary square with corners o, o+u, o+u+v, o+v, split along its
// even diagonal and wound so the normal points along `outward`
void addBoundarySquare(SpringModel& m, const Block& b, const std::array<int, 3>& o,
                       const std::array<int, 3>& u, const std::array<int, 3>& v,
                       const Vec3& outward) {
  auto at = [&](int du, int dv) {
    return b.id(o[0] + du * u[0] + dv * v[0], o[1] + du * u[1] + dv * v[1],
                o[2] + du * u[2] + dv * v[2]);
  };
  const int p00 = at(0, 0), p10 = at(1, 0), p11 = at(1, 1), p01 = at(0, 1);
  std::array<std::array<int, 3>, 2> tris;
  if (Block::even(o[0], o[1], o[2]))
    tris = {{{p00, p10, p11}, {p00, p11, p01}}};
  else
    tris = {{{p10, p11, p01}, {p10, p01, p00}}};
  for (auto t : tris) {
    const auto x = m.restPositions();
    const Vec3 n = (x.col(t[1]) - x.col(t[0])).cross(x.col(t[2]) - x.col(t[0]));
    if (n.dot(outward) < 0.0) std::swap(t[1], t[2]);
    m.addTriangle(t[0], t[1], t[2]);
  }
}

}  // namespace

TetraMesh tetraLattice(const TetraLatticeDef& def) {
  assert(def.nx >= 2 && def.ny >= 2 && def.nz >= 2 && def.spacing > 0.0);
  const Block b{def.nx, def.ny, def.nz};
  TetraMesh out;
  SpringModel& m = out.model;

  // nodes x fastest, z slowest
  for (int z = 0; z < b.nz; ++z)
    for (int y = 0; y < b.ny; ++y)
      for (int x = 0; x < b.nx; ++x) m.addNode(Vec3(x, y, z) * def.spacing, def.mass);

  // per node: axis links forward, then the diagonals of the face squares it is the
  // lowest corner of
  constexpr std::array<int, 3> ex{1, 0, 0}, ey{0, 1, 0}, ez{0, 0, 1};
  for (int z = 0; z < b.nz; ++z) {
    for (int y = 0; y < b.ny; ++y) {
      for (int x = 0; x < b.nx; ++x) {
        const int i = b.id(x, y, z);
        const bool fx = x + 1 < b.nx, fy = y + 1 < b.ny, fz = z + 1 < b.nz;
        if (fx) m.addLink(i, b.id(x + 1, y, z), def.k);
        if (fy) m.addLink(i, b.id(x, y + 1, z), def.k);
        if (fz) m.addLink(i, b.id(x, y, z + 1), def.k);
        const std::array<int, 3> o{x, y, z};
        if (fx && fy) {
          const auto [p, q] = faceDiagonal(b, o, ex, ey);
          m.addLink(p, q, def.k);
        }
        if (fx && fz) {
          const auto [p, q] = faceDiagonal(b, o, ex, ez);
          m.addLink(p, q, def.k);
        }
        if (fy && fz) {
          const auto [p, q] = faceDiagonal(b, o, ey, ez);
          m.addLink(p, q, def.k);
        }
      }
    }
  }

  // five tetrahedra per cube; odd cubes mirror the even split in x
  using Corner = std::array<int, 3>;
  static constexpr std::array<std::array<Corner, 4>, 5> kEvenSplit{{
      {{{0, 0, 0}, {1, 1, 0}, {1, 0, 1}, {0, 1, 1}}},
      {{{1, 0, 0}, {0, 0, 0}, {1, 1, 0}, {1, 0, 1}}},
      {{{0, 1, 0}, {0, 0, 0}, {0, 1, 1}, {1, 1, 0}}},
      {{{0, 0, 1}, {0, 0, 0}, {1, 0, 1}, {0, 1, 1}}},
      {{{1, 1, 1}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}}},
  }};
  const auto rest = m.restPositions();
  for (int z = 0; z + 1 < b.nz; ++z) {
    for (int y = 0; y + 1 < b.ny; ++y) {
      for (int x = 0; x + 1 < b.nx; ++x) {
        const bool even = Block::even(x, y, z);
        for (const auto& tet : kEvenSplit) {
          std::array<int, 4> t{};
          for (int c = 0; c < 4; ++c) {
            const int cx = even ? tet[c][0] : 1 - tet[c][0];
            t[c] = b.id(x + cx, y + tet[c][1], z + tet[c][2]);
          }
          const Vec3 a = rest.col(t[0]);
          const double volume =
              (rest.col(t[1]) - a).cross(rest.col(t[2]) - a).dot(rest.col(t[3]) - a);
          if (volume < 0.0) std::swap(t[2], t[3]);
          out.tetrahedra.push_back(t);
        }
      }
    }
  }

  // boundary squares of the six faces
  const int ex1 = b.nx - 1, ey1 = b.ny - 1, ez1 = b.nz - 1;
  for (int y = 0; y < ey1; ++y)
    for (int x = 0; x < ex1; ++x) {
      addBoundarySquare(m, b, {x, y, 0}, ex, ey, -Vec3::UnitZ());
      addBoundarySquare(m, b, {x, y, ez1}, ex, ey, Vec3::UnitZ());
    }
  for (int z = 0; z < ez1; ++z)
    for (int x = 0; x < ex1; ++x) {
      addBoundarySquare(m, b, {x, 0, z}, ex, ez, -Vec3::UnitY());
      addBoundarySquare(m, b, {x, ey1, z}, ex, ez, Vec3::UnitY());
    }
  for (int z = 0; z < ez1; ++z)
    for (int y = 0; y < ey1; ++y) {
      addBoundarySquare(m, b, {0, y, z}, ey, ez, -Vec3::UnitX());
      addBoundarySquare(m, b, {ex1, y, z}, ey, ez, Vec3::UnitX());
    }

  if (def.fixBottom)
    for (int y = 0; y < b.ny; ++y)
      for (int x = 0; x < b.nx; ++x) m.setFixed(b.id(x, y, 0));

  m.finalize();
  return out;
}

}  // namespace microsim::sim
