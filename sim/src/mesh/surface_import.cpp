#include "microsim/sim/mesh/surface_import.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <algorithm>
#include <cmath>
#include <exception>
#include <filesystem>
#include <map>
#include <set>
#include <system_error>
#include <utility>

namespace microsim::sim {

namespace {

bool validOptions(const SurfaceMeshOptions& o) {
  return std::isfinite(o.scale) && o.scale > 0.0 && std::isfinite(o.weldTolerance) &&
         o.weldTolerance > 0.0 && std::isfinite(o.k) && o.k >= 0.0 && std::isfinite(o.mass) &&
         o.mass > 0.0;
}

// vertex → node: identity, or the first vertex of each weld cell in vertex order
std::vector<int> weldMap(const Points& x, const SurfaceMeshOptions& o, int& nodeCount) {
  const int n = static_cast<int>(x.cols());
  std::vector<int> map(n);
  nodeCount = 0;
  if (!o.weld) {
    for (int i = 0; i < n; ++i) map[i] = nodeCount++;
    return map;
  }
  std::map<std::array<long long, 3>, int> cells;
  for (int i = 0; i < n; ++i) {
    std::array<long long, 3> key{};
    for (int c = 0; c < 3; ++c) key[c] = std::llround(x(c, i) / o.weldTolerance);
    const auto [it, inserted] = cells.try_emplace(key, nodeCount);
    if (inserted) ++nodeCount;
    map[i] = it->second;
  }
  return map;
}

}  // namespace

SurfaceImport springMeshFromTriangles(const Points& vertices,
                                      const std::vector<std::array<int, 3>>& triangles,
                                      const SurfaceMeshOptions& options) {
  if (!validOptions(options)) return MeshImportError{MeshImportErrorKind::BadOptions, {}};
  if (!vertices.allFinite()) return MeshImportError{MeshImportErrorKind::NonFiniteCoords, {}};
  const Points x = vertices * options.scale;
  if (!x.allFinite()) return MeshImportError{MeshImportErrorKind::NonFiniteCoords, {}};

  // weld, then keep the triangles whose corners are three distinct nodes
  int nodes = 0;
  const std::vector<int> node = weldMap(x, options, nodes);
  const int vertexCount = static_cast<int>(x.cols());
  std::vector<std::array<int, 3>> kept;
  kept.reserve(triangles.size());
  for (const auto& t : triangles) {
    if (std::any_of(t.begin(), t.end(), [&](int v) { return v < 0 || v >= vertexCount; })) continue;
    const std::array<int, 3> w{node[t[0]], node[t[1]], node[t[2]]};
    if (w[0] == w[1] || w[1] == w[2] || w[0] == w[2]) continue;
    kept.push_back(w);
  }
  if (kept.empty()) return MeshImportError{MeshImportErrorKind::NoTriangles, {}};

  // nodes at their first vertex's position; only nodes used by a triangle survive
  std::vector<int> firstVertex(nodes, -1);
  for (int v = vertexCount - 1; v >= 0; --v) firstVertex[node[v]] = v;
  std::vector<char> used(nodes, 0);
  for (const auto& t : kept)
    for (int v : t) used[v] = 1;
  std::vector<int> renumber(nodes, -1);
  SpringModel m;
  for (int i = 0; i < nodes; ++i)
    if (used[i]) renumber[i] = m.addNode(x.col(firstVertex[i]), options.mass);

  // triangles, then unique edges in first-seen order
  std::set<std::pair<int, int>> seen;
  for (auto t : kept) {
    for (int& v : t) v = renumber[v];
    m.addTriangle(t[0], t[1], t[2]);
    for (int e = 0; e < 3; ++e) {
      const int a = t[e];
      const int b = t[(e + 1) % 3];
      if (seen.insert({std::min(a, b), std::max(a, b)}).second) m.addLink(a, b, options.k);
    }
  }
  m.finalize();
  return m;
}

SurfaceImport importSurfaceMesh(const std::string& path, const SurfaceMeshOptions& options) {
  if (!validOptions(options)) return MeshImportError{MeshImportErrorKind::BadOptions, {}};
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    return MeshImportError{MeshImportErrorKind::FileNotFound, {}};

  try {
    // triangulated, transforms baked in, every mesh gathered in scene order
    Assimp::Importer importer;
    const aiScene* scene =
        importer.ReadFile(path, aiProcess_ValidateDataStructure | aiProcess_Triangulate |
                                    aiProcess_PreTransformVertices);
    if (scene == nullptr || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) != 0)
      return MeshImportError{MeshImportErrorKind::Unreadable, importer.GetErrorString()};

    long long total = 0;
    for (unsigned mi = 0; mi < scene->mNumMeshes; ++mi) total += scene->mMeshes[mi]->mNumVertices;
    Points vertices(3, total);
    std::vector<std::array<int, 3>> triangles;
    int base = 0;
    for (unsigned mi = 0; mi < scene->mNumMeshes; ++mi) {
      const aiMesh* mesh = scene->mMeshes[mi];
      for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
        const aiVector3D& p = mesh->mVertices[v];
        vertices.col(base + v) = Vec3(p.x, p.y, p.z);
      }
      for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
        const aiFace& face = mesh->mFaces[f];
        if (face.mNumIndices != 3) continue;
        triangles.push_back({base + static_cast<int>(face.mIndices[0]),
                             base + static_cast<int>(face.mIndices[1]),
                             base + static_cast<int>(face.mIndices[2])});
      }
      base += static_cast<int>(mesh->mNumVertices);
    }
    return springMeshFromTriangles(vertices, triangles, options);
  } catch (const std::exception& e) {
    return MeshImportError{MeshImportErrorKind::Unreadable, e.what()};
  } catch (...) {
    return MeshImportError{MeshImportErrorKind::Unreadable, {}};
  }
}

}  // namespace microsim::sim
