#pragma once
// Spring meshes from triangulated surfaces: any file assimp reads (OBJ, glTF/GLB, STL,
// PLY, ...) becomes a SpringModel whose nodes are the surface's vertices, whose links
// are its unique triangle edges (rest length = the edge's length in the file) and whose
// triangles are the surface's, for rendering and collision.
//
// Files that export per-face normals or UVs split a vertex into copies at the same
// position (every STL does); welding merges vertices whose coordinates round to the
// same multiple of `weldTolerance` so the surface is one connected membrane.
// Triangles that welding collapses (two corners on one node) are dropped.
//
// Failures come back as values, never exceptions: a missing file, a file assimp cannot
// parse (its message is kept as data), a scene without a single triangle, or
// non-finite coordinates. Callers turn the enum into words.

#include "microsim/sim/mesh/spring_model.h"

#include <array>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

namespace microsim::sim {

struct SurfaceMeshOptions {
  bool weld = true;             ///< merge vertices at (nearly) the same position
  double weldTolerance = 1e-9;  ///< weld grid cell (mm, after scaling), > 0
  double scale = 1.0;           ///< mm per file unit (e.g. 1000 for a file in metres)
  double k = 10.0;              ///< stiffness of every link (g/s²)
  double mass = 1.0;            ///< mass of every node (g)
};

enum class MeshImportErrorKind : std::uint8_t {
  FileNotFound,     ///< no such file, or not a regular file
  Unreadable,       ///< assimp could not parse it (message in `detail`)
  NoTriangles,      ///< parsed, but held no triangle
  NonFiniteCoords,  ///< a vertex coordinate is NaN or infinite
  BadOptions,       ///< scale, tolerance, stiffness or mass out of range
};

struct MeshImportError {
  MeshImportErrorKind kind = MeshImportErrorKind::Unreadable;
  std::string detail;  ///< assimp's own message for Unreadable, else empty
};

/// The result of an import: the model (finalized) or why there is none.
using SurfaceImport = std::variant<SpringModel, MeshImportError>;

/// Builds the spring mesh of a triangle soup. `vertices` is 3 by #V (file units),
/// `triangles` index into it. Indices out of range fail as NoTriangles when no valid
/// triangle remains, and are otherwise skipped.
SurfaceImport springMeshFromTriangles(const Points& vertices,
                                      const std::vector<std::array<int, 3>>& triangles,
                                      const SurfaceMeshOptions& options = {});

/// Reads `path` with assimp (triangulated, node transforms applied, every mesh of the
/// file merged) and builds its spring mesh.
SurfaceImport importSurfaceMesh(const std::string& path, const SurfaceMeshOptions& options = {});

}  // namespace microsim::sim
