#include "microsim/sim/mesh/surface_import.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

namespace microsim::sim {
namespace {

namespace fs = std::filesystem;

const std::string kCube = std::string(MICROSIM_SOURCE_DIR) + "/resources/meshes/cube.obj";

// a scratch directory per test, removed afterwards
class SurfaceImportFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / (std::string("microsim_surface_import_") + info->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }
  fs::path dir_;
};

const SpringModel& model(const SurfaceImport& r) {
  return std::get<SpringModel>(r);
}
MeshImportErrorKind kind(const SurfaceImport& r) {
  return std::get<MeshImportError>(r).kind;
}

TEST(SurfaceImport, CubeObjWeldsToEightNodes) {
  const SurfaceImport r = importSurfaceMesh(kCube);
  ASSERT_TRUE(std::holds_alternative<SpringModel>(r));
  const SpringModel& m = model(r);
  EXPECT_EQ(m.nodeCount(), 8);
  EXPECT_EQ(m.triangles().size(), 12u);
  EXPECT_EQ(m.linkCount(), 18);
  EXPECT_TRUE(m.finalized());
  for (const Link& l : m.links()) {
    EXPECT_TRUE(l.rest == 2.0 || std::abs(l.rest - std::sqrt(8.0)) < 1e-12) << l.rest;
    EXPECT_EQ(l.k, 10.0);
  }
  // outward winding survives import
  for (const auto& t : m.triangles()) {
    const Points& x = m.restPositions();
    const Vec3 n = (x.col(t[1]) - x.col(t[0])).cross(x.col(t[2]) - x.col(t[0]));
    EXPECT_GT(n.dot(x.col(t[0]) + x.col(t[1]) + x.col(t[2])), 0.0);
  }
}

TEST(SurfaceImport, WithoutWeldingEveryFaceIsItsOwnPatch) {
  SurfaceMeshOptions o;
  o.weld = false;
  o.scale = 0.5;
  o.k = 3.0;
  const SurfaceImport r = importSurfaceMesh(kCube, o);
  ASSERT_TRUE(std::holds_alternative<SpringModel>(r));
  const SpringModel& m = model(r);
  EXPECT_GE(m.nodeCount(), 24);
  EXPECT_EQ(m.linkCount(), 6 * 5);
  EXPECT_DOUBLE_EQ(m.restPositions().maxCoeff(), 0.5);
  EXPECT_EQ(m.link(0).k, 3.0);
}

TEST_F(SurfaceImportFiles, AsciiStlPlyAndGltf) {
  const std::string stl =
      write("tri.stl",
            "solid t\n"
            " facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n   vertex 0 1 0\n"
            "  endloop\n endfacet\n"
            " facet normal 0 0 1\n  outer loop\n   vertex 1 0 0\n   vertex 1 1 0\n   vertex 0 1 0\n"
            "  endloop\n endfacet\n"
            "endsolid t\n");
  const SurfaceImport s = importSurfaceMesh(stl);
  ASSERT_TRUE(std::holds_alternative<SpringModel>(s));
  EXPECT_EQ(model(s).nodeCount(), 4);
  EXPECT_EQ(model(s).linkCount(), 5);

  const std::string ply =
      write("quad.ply",
            "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
            "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
            "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n");
  const SurfaceImport p = importSurfaceMesh(ply);
  ASSERT_TRUE(std::holds_alternative<SpringModel>(p));
  EXPECT_EQ(model(p).triangles().size(), 2u);
  EXPECT_EQ(model(p).linkCount(), 5);

  // a tetrahedron placed by a node transform at x = 10
  const std::string gltf = write(
      "tet.gltf",
      R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],)"
      R"("nodes":[{"mesh":0,"translation":[10,0,0]}],)"
      R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],)"
      R"("buffers":[{"byteLength":72,"uri":"data:application/octet-stream;base64,)"
      R"(AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAAAAAAAAAAAAIA/AAACAAEAAAABAAMAAAADAAIAAQACAAMA"}],)"
      R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":48},{"buffer":0,"byteOffset":48,"byteLength":24}],)"
      R"("accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3","min":[0,0,0],"max":[1,1,1]},)"
      R"({"bufferView":1,"componentType":5123,"count":12,"type":"SCALAR"}]})");
  const SurfaceImport g = importSurfaceMesh(gltf);
  ASSERT_TRUE(std::holds_alternative<SpringModel>(g)) << std::get<MeshImportError>(g).detail;
  EXPECT_EQ(model(g).nodeCount(), 4);
  EXPECT_EQ(model(g).linkCount(), 6);
  EXPECT_EQ(model(g).triangles().size(), 4u);
  EXPECT_DOUBLE_EQ(model(g).restPositions().row(0).minCoeff(), 10.0);
}

TEST_F(SurfaceImportFiles, FailuresAreValues) {
  EXPECT_EQ(kind(importSurfaceMesh((dir_ / "missing.obj").string())),
            MeshImportErrorKind::FileNotFound);
  EXPECT_EQ(kind(importSurfaceMesh(dir_.string())), MeshImportErrorKind::FileNotFound);

  // a ply whose header promises more than the file holds
  const SurfaceImport truncated = importSurfaceMesh(
      write("bad.ply",
            "ply\nformat binary_little_endian 1.0\nelement vertex 1000\nproperty float x\n"
            "property float y\nproperty float z\nelement face 1000\n"
            "property list uchar int vertex_indices\nend_header\n\x01\x02"));
  ASSERT_TRUE(std::holds_alternative<MeshImportError>(truncated));
  EXPECT_TRUE(kind(truncated) == MeshImportErrorKind::Unreadable ||
              kind(truncated) == MeshImportErrorKind::NoTriangles);

  // binary garbage under a known extension
  const SurfaceImport garbage =
      importSurfaceMesh(write("garbage.glb", std::string("glTF\x02\0\0\0\xff\xff", 10)));
  ASSERT_TRUE(std::holds_alternative<MeshImportError>(garbage));
  EXPECT_EQ(kind(garbage), MeshImportErrorKind::Unreadable);
  EXPECT_FALSE(std::get<MeshImportError>(garbage).detail.empty());

  // points only
  const SurfaceImport points = importSurfaceMesh(write("points.obj", "v 0 0 0\nv 1 0 0\np 1 2\n"));
  ASSERT_TRUE(std::holds_alternative<MeshImportError>(points));
  EXPECT_TRUE(kind(points) == MeshImportErrorKind::NoTriangles ||
              kind(points) == MeshImportErrorKind::Unreadable);

  // more corruption: none may crash, each must fail as a value
  const std::string corrupt[] = {
      write("empty.obj", ""),
      write("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\n"),
      write("short.stl", std::string(84, '\0') + "\x05"),
      write("stl_count.stl", std::string(80, 'x') + std::string("\xff\xff\x00\x00", 4)),
      write("text.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"meshes\": [{\"primitives\""),
      write("nan.ply",
            "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
            "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
            "end_header\n0 0 0\n1 0 0\n0 nan 0\n3 0 1 2\n"),
  };
  for (const std::string& file : corrupt) {
    const SurfaceImport r = importSurfaceMesh(file);
    EXPECT_TRUE(std::holds_alternative<MeshImportError>(r)) << file;
  }

  SurfaceMeshOptions o;
  o.scale = 0.0;
  EXPECT_EQ(kind(importSurfaceMesh(kCube, o)), MeshImportErrorKind::BadOptions);
}

TEST(SurfaceImport, TriangleSoupKernel) {
  Points x(3, 5);
  x << 0, 1, 0, 1, 1e-12,  //
      0, 0, 1, 1, 0,       //
      0, 0, 0, 0, 0;
  // vertex 4 welds onto vertex 0, so the last triangle collapses
  const std::vector<std::array<int, 3>> tris{{0, 1, 2}, {1, 3, 2}, {4, 0, 1}, {0, 1, 7}};
  const SurfaceImport r = springMeshFromTriangles(x, tris);
  ASSERT_TRUE(std::holds_alternative<SpringModel>(r));
  EXPECT_EQ(model(r).nodeCount(), 4);
  EXPECT_EQ(model(r).triangles().size(), 2u);
  EXPECT_EQ(model(r).linkCount(), 5);

  Points bad = x;
  bad(1, 3) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(kind(springMeshFromTriangles(bad, tris)), MeshImportErrorKind::NonFiniteCoords);
  bad(1, 3) = std::numeric_limits<double>::infinity();
  EXPECT_EQ(kind(springMeshFromTriangles(bad, tris)), MeshImportErrorKind::NonFiniteCoords);
  EXPECT_EQ(kind(springMeshFromTriangles(x, {{0, 0, 1}})), MeshImportErrorKind::NoTriangles);
  EXPECT_EQ(kind(springMeshFromTriangles(x, {})), MeshImportErrorKind::NoTriangles);
}

}  // namespace
}  // namespace microsim::sim
