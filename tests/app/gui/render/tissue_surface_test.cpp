// The tissue as drawn, without GL: the end faces of each vessel get vertices of their own in
// the cut face's colour, the lumen darkens with depth from the nearer end, every vertex
// carries its rest point in its vessel's frame and its layer, and the snapshot places copies
// where their nodes are.
#include "gui/render/tissue_surface.h"

#include "gui/render/draw_list.h"

#include "microsim/sim/scene/scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <variant>

namespace microsim::gui {
namespace {

const std::string kTissueSurfaceScene = std::string(MICROSIM_SOURCE_DIR) + "/resources/scenes/anastomosis.json";

// the scene as shipped, drawn with its simulated triangles as they are (`subdivision` 0) or smooth
sim::SceneDef loadTissueSurfaceScene(int subdivision = 0) {
  sim::SceneDefLoad load = sim::loadSceneDef(kTissueSurfaceScene);
  EXPECT_TRUE(std::holds_alternative<sim::SceneDef>(load));
  auto def = std::get<sim::SceneDef>(std::move(load));
  def.surface.subdivision = subdivision;
  return def;
}

// the scene after one step with the hands still, as the viewport receives it
sim::RenderSnapshot snapshotAfterOneStep(sim::Scene& scene) {
  sim::InputFrame frame;
  frame.time = scene.dt();
  scene.step(frame);
  sim::RenderSnapshot snapshot;
  sim::fillSnapshot(scene, snapshot);
  return snapshot;
}

QVector3D colourOf(const TissueSurface& s, std::size_t vertex) {
  return {s.colours[3 * vertex], s.colours[3 * vertex + 1], s.colours[3 * vertex + 2]};
}

float layerOf(const TissueSurface& s, std::size_t vertex) { return s.surface[4 * vertex + 3]; }

TEST(TissueSurface, EndFacesDrawCopiesOfTheirNodesInTheCutFacesColour) {
  const sim::SceneDef def = loadTissueSurfaceScene();
  const auto& triangles = def.tissue.model.triangles();
  const TissueSurface s = tissueSurface(def, triangles);
  const auto nodes = static_cast<std::size_t>(def.tissue.model.nodeCount());
  ASSERT_EQ(s.indices.size(), 3 * triangles.size());
  ASSERT_EQ(s.colours.size(), 3 * s.source.size());
  ASSERT_EQ(s.surface.size(), 4 * s.source.size());
  ASSERT_FALSE(def.vessels.empty());

  int endTriangles = 0;
  for (const sim::SceneVessel& v : def.vessels)
    endTriangles += (v.clampedEnd.end - v.clampedEnd.begin) + (v.cutEnd.end - v.cutEnd.begin);
  ASSERT_GT(endTriangles, 0);
  EXPECT_GT(s.source.size(), nodes) << "the end annuli have vertices of their own";

  // every triangle is drawn once over the same nodes; end-face vertices are copies
  int copiesUsed = 0;
  for (std::size_t t = 0; t < s.indices.size() / 3; ++t) {
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t vertex = s.indices[3 * t + k];
      ASSERT_LT(vertex, s.source.size());
      if (vertex < nodes) {
        EXPECT_EQ(s.source[vertex], static_cast<int>(vertex));
        EXPECT_NE(layerOf(s, vertex), static_cast<float>(TissueLayer::CutFace));
      } else {
        ++copiesUsed;
        EXPECT_EQ(layerOf(s, vertex), static_cast<float>(TissueLayer::CutFace));
        EXPECT_EQ(colourOf(s, vertex), kVesselCutFace);
        // the copy's surface point is its node's
        const auto node = static_cast<std::size_t>(s.source[vertex]);
        for (std::size_t c = 0; c < 3; ++c) EXPECT_EQ(s.surface[4 * vertex + c], s.surface[4 * node + c]);
      }
    }
  }
  EXPECT_EQ(copiesUsed, 3 * endTriangles);
  // the cut face is paler than the outer wall: the wall's thickness reads
  EXPECT_GT(kVesselCutFace.y(), kVesselOuter.y() + 0.2f);
}

TEST(TissueSurface, TheLumenDarkensWithDepthAndEveryVertexKnowsItsPlaceOnTheWall) {
  const sim::SceneDef def = loadTissueSurfaceScene();
  const auto& triangles = def.tissue.model.triangles();
  const TissueSurface s = tissueSurface(def, triangles);
  for (const sim::SceneVessel& v : def.vessels) {
    const double inner = v.def.radius - v.def.wallThickness;
    float brightestLumen = 0.0f;
    float darkestLumen = 1.0f;
    for (const auto& [range, layer, radius] : {std::tuple{v.outerSurface, TissueLayer::OuterWall, v.def.radius},
                                               std::tuple{v.innerSurface, TissueLayer::Lumen, inner}}) {
      for (int t = range.begin; t < range.end; ++t) {
        for (int i : triangles[static_cast<std::size_t>(t)]) {
          const auto k = static_cast<std::size_t>(i);
          EXPECT_EQ(layerOf(s, k), static_cast<float>(layer));
          // the rest point in the vessel's frame: along the axis within its length, across it
          // at the hull's radius
          const float along = s.surface[4 * k];
          EXPECT_GE(along, -1e-4f);
          EXPECT_LE(along, static_cast<float>(v.def.length) + 1e-4f);
          EXPECT_NEAR(std::hypot(s.surface[4 * k + 1], s.surface[4 * k + 2]), radius, 1e-4);
          if (layer == TissueLayer::OuterWall) {
            EXPECT_EQ(colourOf(s, k), kVesselOuter);
          } else {
            const float red = colourOf(s, k).x();
            EXPECT_LE(red, kVesselLumen.x() + 1e-6f);
            EXPECT_GE(red, kLumenDeepest * kVesselLumen.x() - 1e-6f);
            brightestLumen = std::max(brightestLumen, red);
            darkestLumen = std::min(darkestLumen, red);
          }
        }
      }
    }
    // the mouth of the lumen keeps its colour, its depth is far darker
    EXPECT_NEAR(brightestLumen, kVesselLumen.x(), 1e-5);
    EXPECT_LT(darkestLumen, 0.6f * kVesselLumen.x());
  }
}

TEST(TissueSurface, TheSnapshotPlacesEveryVertexAtItsNode) {
  const sim::SceneDef def = loadTissueSurfaceScene();
  sim::Scene scene(def);
  const sim::RenderSnapshot snapshot = snapshotAfterOneStep(scene);
  TissueSurface s = tissueSurface(def, scene.tissue().triangles());
  ASSERT_FALSE(s.smooth);
  ShadedMesh mesh;
  placeTissue(s, snapshot, mesh);
  ASSERT_EQ(mesh.vertices.size(), s.source.size());
  for (std::size_t v = 0; v < s.source.size(); ++v) {
    const auto n = 3 * static_cast<std::size_t>(s.source[v]);
    for (std::size_t r = 0; r < 3; ++r) {
      ASSERT_EQ(mesh.vertices[v].position[r], snapshot.tissuePositions[n + r]) << v;
      ASSERT_EQ(mesh.vertices[v].normal[r], snapshot.tissueNormals[n + r]) << v;
    }
  }
}

TEST(TissueSurface, ASmoothSurfaceDrawsTheVesselRoundWithCrispRimsAndThroughEveryNode) {
  const sim::SceneDef def = loadTissueSurfaceScene(2);
  sim::Scene scene(def);
  const sim::RenderSnapshot snapshot = snapshotAfterOneStep(scene);
  const auto& triangles = scene.tissue().triangles();
  TissueSurface s = tissueSurface(def, triangles);
  ASSERT_TRUE(s.smooth);
  EXPECT_EQ(s.indices.size(), 3 * 16 * triangles.size())
      << "two levels: 16 drawn triangles a simulated one";
  ShadedMesh mesh;
  placeTissue(s, snapshot, mesh);
  ASSERT_EQ(mesh.vertices.size(), s.source.size());

  // the surface passes through every node where the snapshot has it
  const auto& onNode = s.smooth->nodeVertices();
  for (std::size_t n = 0; n < onNode.size(); ++n) {
    ASSERT_GE(onNode[n], 0);
    for (std::size_t r = 0; r < 3; ++r)
      EXPECT_NEAR(mesh.vertices[static_cast<std::size_t>(onNode[n])].position[r],
                  snapshot.tissuePositions[3 * n + r], 1e-5f);
  }
  // the walls round, their normals straight out (or in, for the lumen); the cut faces flat,
  // their normals along the axis right up to the rims
  for (const sim::SceneVessel& v : def.vessels) {
    const sim::Vec3 axis = v.def.direction.normalized();
    for (std::size_t vertex = 0; vertex < s.source.size(); ++vertex) {
      const auto& drawn = mesh.vertices[vertex];
      const sim::Vec3 p(drawn.position[0], drawn.position[1], drawn.position[2]);
      const sim::Vec3 n(drawn.normal[0], drawn.normal[1], drawn.normal[2]);
      const double along = (p - v.def.origin).dot(axis);
      if (along < 0.05 || along > v.def.length - 0.05) continue;  // the other end, or near a rim
      const sim::Vec3 across = (p - v.def.origin) - along * axis;
      const double r = across.norm();
      if (std::abs(r - v.def.radius) > 2e-3) continue;  // not this vessel's outer wall
      if (layerOf(s, vertex) != static_cast<float>(TissueLayer::OuterWall)) continue;
      EXPECT_GT(n.dot(across / r), 0.995) << vertex;
    }
    int cutFaceVertices = 0;
    for (std::size_t vertex = 0; vertex < s.source.size(); ++vertex) {
      if (layerOf(s, vertex) != static_cast<float>(TissueLayer::CutFace)) continue;
      const auto& drawn = mesh.vertices[vertex];
      const sim::Vec3 p(drawn.position[0], drawn.position[1], drawn.position[2]);
      const double along = (p - v.def.origin).dot(axis);
      if (std::abs(along - v.def.length) > 1e-3) continue;  // another face
      ++cutFaceVertices;
      const sim::Vec3 n(drawn.normal[0], drawn.normal[1], drawn.normal[2]);
      EXPECT_GT(std::abs(n.dot(axis)), 0.999) << vertex;
    }
    EXPECT_GT(cutFaceVertices, 16 * 4) << "the cut face is refined as well";
  }
}

}  // namespace
}  // namespace microsim::gui
