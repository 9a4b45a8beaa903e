#include "microsim/sim/scene/spring_scene.h"

#include "microsim/sim/mesh/lattice.h"
#include "microsim/sim/mesh/tetra_lattice.h"
#include "microsim/sim/mesh/vessel.h"
#include "microsim/sim/scene/json_location.h"

#include <gtest/gtest.h>

#include <string>

namespace microsim::sim {
namespace {

const std::string kTestScenes = std::string(MICROSIM_TEST_DATA_DIR) + "/scenes/";

const SpringScene& sceneOf(const SceneLoad& r) {
  return std::get<SpringScene>(r);
}

SceneError springSceneErrorOf(const std::string& text) {
  const SceneLoad r = parseSpringScene(text, "t.json");
  EXPECT_TRUE(std::holds_alternative<SceneError>(r)) << text;
  return std::holds_alternative<SceneError>(r) ? std::get<SceneError>(r) : SceneError{};
}

// a one-object spring-mesh scene with `extra` spliced into the object
std::string mesh(const std::string& links, const std::string& extra = "") {
  return R"({"objects": [{"type": "spring-mesh", "nodes": [[0,0,0], [1,0,0], [0,1,0]], "links": )" +
         links + extra + "}]}";
}

TEST(SpringScene, TwoNodeFileAsInDesign) {
  const SceneLoad r = loadSpringScene(kTestScenes + "two_node.json");
  ASSERT_TRUE(std::holds_alternative<SpringScene>(r));
  const SpringScene& s = sceneOf(r);
  EXPECT_EQ(s.model.nodeCount(), 2);
  ASSERT_EQ(s.model.linkCount(), 1);
  EXPECT_EQ(s.model.link(0).k, 50.0);
  EXPECT_EQ(s.model.link(0).rest, 1.0);
  EXPECT_TRUE(s.model.isFixed(0));
  EXPECT_FALSE(s.model.isFixed(1));
  ASSERT_EQ(s.controls.size(), 1);
  EXPECT_EQ(s.controls.nodes[0], 1);
  EXPECT_EQ(Vec3(s.controls.targets.col(0)), Vec3(1, 0, 1));
  EXPECT_EQ(s.model.gravity, Vec3::Zero());
  ASSERT_EQ(s.objects.size(), 1u);
  EXPECT_EQ(s.objects[0].name, "pair");
  EXPECT_TRUE(s.model.finalized());
  EXPECT_FALSE(s.solver.name.has_value());
}

TEST(SpringScene, EveryObjectTypeMergesInOrder) {
  const SceneLoad r = loadSpringScene(kTestScenes + "mixed.json");
  ASSERT_TRUE(std::holds_alternative<SpringScene>(r))
      << static_cast<int>(std::get<SceneError>(r).kind) << " " << std::get<SceneError>(r).field;
  const SpringScene& s = sceneOf(r);
  ASSERT_EQ(s.objects.size(), 6u);
  const int nodes[] = {27, 48, 12, 12, 8, 2};
  const int links[] = {126,       static_cast<int>(vesselLinkCount(4, 6)),
                       3 * 6 + 5, static_cast<int>(tetraLatticeLinkCount(3, 2, 2)),
                       18,        1};
  int firstNode = 0;
  int firstLink = 0;
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(s.objects[i].firstNode, firstNode) << i;
    EXPECT_EQ(s.objects[i].nodeCount, nodes[i]) << i;
    EXPECT_EQ(s.objects[i].firstLink, firstLink) << i;
    EXPECT_EQ(s.objects[i].linkCount, links[i]) << i;
    firstNode += nodes[i];
    firstLink += links[i];
  }
  EXPECT_EQ(s.model.nodeCount(), firstNode);
  EXPECT_EQ(s.model.linkCount(), firstLink);
  EXPECT_EQ(s.objects[4].type, "surface-mesh");
  EXPECT_EQ(s.objects[4].name, "cube");

  // links of later objects point at their own shifted nodes
  const SceneObject& v = s.objects[1];
  for (int li = v.firstLink; li < v.firstLink + v.linkCount; ++li) {
    EXPECT_GE(s.model.link(li).a, v.firstNode);
    EXPECT_LT(s.model.link(li).b, v.firstNode + v.nodeCount);
  }
  // generator options took effect
  EXPECT_EQ(s.model.link(0).k, 20.0);
  EXPECT_NEAR(s.model.restPositions()(0, v.firstNode + 6 * 2 * 3), 7.0, 1e-12);
  EXPECT_TRUE(s.model.isFixed(v.firstNode));
  EXPECT_EQ(s.model.link(s.objects[5].firstLink).rest, 1.5);
  EXPECT_TRUE(s.model.isFixed(s.objects[4].firstNode));
  EXPECT_DOUBLE_EQ(s.model.restPositions().col(s.objects[4].firstNode).cwiseAbs().maxCoeff(), 0.5);
  EXPECT_EQ(s.model.fixedNodes().size(), 9u + 12u + 10u + 6u + 1u);

  // controls, gravity and solver settings
  ASSERT_EQ(s.controls.size(), 1);
  EXPECT_EQ(s.controls.nodes[0], latticeTopMiddle(3));
  EXPECT_EQ(Vec3(s.controls.targets.col(0)), Vec3(1, 1, 3));
  EXPECT_EQ(s.model.gravity, Vec3(0, 0, -9810));
  EXPECT_EQ(s.solver.name.value_or(""), "qss");
  EXPECT_EQ(s.solver.alpha.value_or(0), 0.01);
  EXPECT_EQ(s.solver.cutout.value_or(0), 0.001);
  EXPECT_EQ(s.solver.momentum.value_or(0), 0.5);
  EXPECT_EQ(s.solver.iterations.value_or(0), 20);
  EXPECT_EQ(s.solver.budgetMs.value_or(0), 33.3);
}

TEST(SpringScene, MalformedFileNamesLinePositionAndField) {
  const SceneLoad r = loadSpringScene(kTestScenes + "malformed.json");
  ASSERT_TRUE(std::holds_alternative<SceneError>(r));
  const SceneError& e = std::get<SceneError>(r);
  EXPECT_EQ(e.kind, SceneErrorKind::IndexOutOfRange);
  EXPECT_EQ(e.field, "objects[0].links[1][1]");
  EXPECT_EQ(e.file, kTestScenes + "malformed.json");
  EXPECT_EQ(e.line, 3);
  EXPECT_EQ(e.column, 31);
}

TEST(SpringScene, MissingFile) {
  const SceneLoad r = loadSpringScene(kTestScenes + "no_such_scene.json");
  ASSERT_TRUE(std::holds_alternative<SceneError>(r));
  EXPECT_EQ(std::get<SceneError>(r).kind, SceneErrorKind::FileNotFound);
}

TEST(SpringScene, MalformedJson) {
  const SceneError e = springSceneErrorOf("{\"objects\": [\n  {\"type\": \"lattice\",, }]}");
  EXPECT_EQ(e.kind, SceneErrorKind::MalformedJson);
  EXPECT_EQ(e.line, 2);
  EXPECT_EQ(e.column, 22);
  EXPECT_EQ(springSceneErrorOf("").kind, SceneErrorKind::MalformedJson);
  EXPECT_EQ(springSceneErrorOf("{\"objects\": [NaN]}").kind, SceneErrorKind::MalformedJson);
}

TEST(SpringScene, StructureErrors) {
  EXPECT_EQ(springSceneErrorOf("[]").kind, SceneErrorKind::WrongType);
  EXPECT_EQ(springSceneErrorOf("{}").kind, SceneErrorKind::MissingField);
  EXPECT_EQ(springSceneErrorOf("{}").field, "objects");
  EXPECT_EQ(springSceneErrorOf(R"({"objects": []})").kind, SceneErrorKind::InvalidValue);
  EXPECT_EQ(springSceneErrorOf(R"({"objects": {}})").kind, SceneErrorKind::WrongType);
  EXPECT_EQ(springSceneErrorOf(R"({"objects": [3]})").field, "objects[0]");
  const SceneError unknownTop = springSceneErrorOf(R"({"objects": [], "gravty": [0,0,0]})");
  EXPECT_EQ(unknownTop.kind, SceneErrorKind::UnknownField);
  EXPECT_EQ(unknownTop.field, "gravty");

  const SceneError type = springSceneErrorOf(R"({"objects": [{"type": "sphere"}]})");
  EXPECT_EQ(type.kind, SceneErrorKind::UnknownObjectType);
  EXPECT_EQ(type.field, "objects[0].type");
  EXPECT_EQ(type.column, 23);
  EXPECT_EQ(springSceneErrorOf(R"({"objects": [{"size": [3,3,3]}]})").kind, SceneErrorKind::MissingField);
  EXPECT_EQ(springSceneErrorOf(R"({"objects": [{"type": 4}]})").kind, SceneErrorKind::WrongType);

  const SceneError unknown =
      springSceneErrorOf(R"({"objects": [{"type": "lattice", "size": [3,3,3], "stifness": 4}]})");
  EXPECT_EQ(unknown.kind, SceneErrorKind::UnknownField);
  EXPECT_EQ(unknown.field, "objects[0].stifness");
}

TEST(SpringScene, MissingAndIllTypedFields) {
  const SceneError noLinks =
      springSceneErrorOf(R"({"objects": [{"type": "spring-mesh", "nodes": [[0,0,0]]}]})");
  EXPECT_EQ(noLinks.kind, SceneErrorKind::MissingField);
  EXPECT_EQ(noLinks.field, "objects[0].links");
  EXPECT_EQ(noLinks.column, 14);  // at the object that lacks it

  EXPECT_EQ(springSceneErrorOf(mesh("[[0, 1]]")).field, "objects[0].links[0]");
  EXPECT_EQ(springSceneErrorOf(mesh("[[0, 1]]")).kind, SceneErrorKind::WrongType);
  EXPECT_EQ(springSceneErrorOf(mesh("[[0, 1, \"stiff\"]]")).field, "objects[0].links[0][2]");
  EXPECT_EQ(springSceneErrorOf(mesh("[[0.5, 1, 1]]")).kind, SceneErrorKind::WrongType);
  EXPECT_EQ(springSceneErrorOf(mesh("[[0, 1, 1]]", R"(, "fixed": 0)")).kind, SceneErrorKind::WrongType);
  const SceneError node =
      springSceneErrorOf(R"({"objects": [{"type": "spring-mesh", "nodes": [[0,0]], "links": []}]})");
  EXPECT_EQ(node.kind, SceneErrorKind::WrongType);
  EXPECT_EQ(node.field, "objects[0].nodes[0]");
  EXPECT_EQ(springSceneErrorOf(R"({"objects": [{"type": "lattice", "size": 3}]})").field, "objects[0].size");
  EXPECT_EQ(springSceneErrorOf(R"({"objects": [{"type": "lattice", "size": [3,3,4]}]})").kind,
            SceneErrorKind::InvalidValue);
  EXPECT_EQ(springSceneErrorOf(R"({"objects": [{"type": "lattice", "size": [1,1,1]}]})").kind,
            SceneErrorKind::InvalidValue);
  EXPECT_EQ(springSceneErrorOf(R"({"objects": [{"type": "lattice", "size": [3,3,3], "fix_bottom": 1}]})").kind,
            SceneErrorKind::WrongType);
  EXPECT_EQ(springSceneErrorOf(R"({"objects": [{"type": "surface-mesh"}]})").field, "objects[0].file");
  EXPECT_EQ(springSceneErrorOf(R"({"objects": [{"type": "vessel", "preset": "huge"}]})").field,
            "objects[0].preset");
  EXPECT_EQ(springSceneErrorOf(R"({"objects": [{"type": "vessel", "wall_thickness": 0.6}]})").field,
            "objects[0].wall_thickness");
  EXPECT_EQ(springSceneErrorOf(R"({"objects": [{"type": "vessel", "direction": [0,0,0]}]})").kind,
            SceneErrorKind::InvalidValue);
  EXPECT_EQ(springSceneErrorOf(R"({"objects": [{"type": "grid", "cells": [0, 3]}]})").field,
            "objects[0].cells[0]");
  EXPECT_EQ(
      springSceneErrorOf(R"({"objects": [{"type": "lattice", "size": [3,3,3]}], "solver": {"iterations": 0}})")
          .field,
      "solver.iterations");
  EXPECT_EQ(
      springSceneErrorOf(R"({"objects": [{"type": "lattice", "size": [3,3,3]}], "solver": {"momentum": 1}})")
          .kind,
      SceneErrorKind::InvalidValue);
  EXPECT_EQ(
      springSceneErrorOf(R"({"objects": [{"type": "lattice", "size": [3,3,3]}], "gravity": [0, 0]})").field,
      "gravity");
}

TEST(SpringScene, LinkIndexErrors) {
  const SceneError range = springSceneErrorOf(mesh("[[0, 1, 1], [2, 3, 1]]"));
  EXPECT_EQ(range.kind, SceneErrorKind::IndexOutOfRange);
  EXPECT_EQ(range.field, "objects[0].links[1][1]");
  EXPECT_EQ(springSceneErrorOf(mesh("[[-1, 1, 1]]")).kind, SceneErrorKind::IndexOutOfRange);
  const SceneError self = springSceneErrorOf(mesh("[[0, 1, 1], [2, 2, 1]]"));
  EXPECT_EQ(self.kind, SceneErrorKind::SelfLink);
  EXPECT_EQ(self.field, "objects[0].links[1]");
  EXPECT_EQ(springSceneErrorOf(mesh("[[0, 1, 1]]", R"(, "fixed": [3])")).kind,
            SceneErrorKind::IndexOutOfRange);
}

TEST(SpringScene, NegativeAndNonFiniteValues) {
  const SceneError k = springSceneErrorOf(mesh("[[0, 1, -1]]"));
  EXPECT_EQ(k.kind, SceneErrorKind::NegativeValue);
  EXPECT_EQ(k.field, "objects[0].links[0][2]");
  const SceneError rest = springSceneErrorOf(mesh("[[0, 1, 1, -0.5]]"));
  EXPECT_EQ(rest.kind, SceneErrorKind::NegativeValue);
  EXPECT_EQ(rest.field, "objects[0].links[0][3]");
  EXPECT_EQ(springSceneErrorOf(R"({"objects": [{"type": "lattice", "size": [3,3,3], "stiffness": -2}]})").kind,
            SceneErrorKind::NegativeValue);
  EXPECT_EQ(springSceneErrorOf(R"({"objects": [{"type": "vessel", "k_layer": -50}]})").field,
            "objects[0].k_layer");

  // JSON has no NaN literal, but a number can overflow a double
  const SceneError inf = springSceneErrorOf(mesh("[[0, 1, 1e999]]"));
  EXPECT_EQ(inf.kind, SceneErrorKind::NonFinite);
  EXPECT_EQ(inf.field, "objects[0].links[0][2]");
  EXPECT_EQ(inf.column, static_cast<int>(mesh("[[0, 1, 1e999]]").find("1e999")) + 1);
  const SceneError pos =
      springSceneErrorOf(R"({"objects": [{"type": "spring-mesh", "nodes": [[0,0,-1e400]], "links": []}]})");
  EXPECT_EQ(pos.kind, SceneErrorKind::NonFinite);
  EXPECT_EQ(pos.field, "objects[0].nodes[0][2]");
  EXPECT_EQ(
      springSceneErrorOf(mesh("[[0, 1, 1]]", R"(, "controls": [{"node": 1, "displacement": [0, 1e999, 0]}])"))
          .kind,
      SceneErrorKind::NonFinite);
}

TEST(SpringScene, AGeneratedMeshTooLargeToBuildIsRefusedByName) {
  // 200³ lattice nodes (8 million) would take gigabytes before anything could use them
  const SceneError e = springSceneErrorOf(R"({"objects": [{"type": "lattice", "size": [200, 200, 200]}]})");
  EXPECT_EQ(e.kind, SceneErrorKind::InvalidValue);
  EXPECT_EQ(e.field, "objects[0].size");
}

TEST(SpringScene, ADefaultGridMergesAfterOtherObjects) {
  // found by the spring-scene fuzzer: merging a default 100 by 100 grid after other objects
  // copied every node once per node added (quadratic); the merged counts are the contract
  const SceneLoad r = parseSpringScene(R"({"objects": [
      {"type": "lattice", "size": [3, 3, 3]},
      {"type": "grid", "fixed": [0]},
      {"type": "spring-mesh", "nodes": [[0, 0, 0], [2, 0, 0]], "links": [[0, 1, 5, 1.5]]}]})",
                                       "t.json");
  ASSERT_TRUE(std::holds_alternative<SpringScene>(r));
  const SpringScene& s = sceneOf(r);
  EXPECT_EQ(s.model.nodeCount(), 27 + 101 * 101 + 2);
  EXPECT_EQ(s.model.restPositions().cols(), s.model.nodeCount());
  EXPECT_TRUE(s.model.isFixed(27));
  EXPECT_EQ(s.model.restPositions().col(27 + 101 * 101 + 1), Vec3(2, 0, 0));
}

TEST(SpringScene, ControlErrors) {
  const SceneError dup = springSceneErrorOf(mesh(
      "[[0, 1, 1]]",
      R"(, "controls": [{"node": 1, "displacement": [0,0,1]}, {"node": 1, "displacement": [0,0,2]}])"));
  EXPECT_EQ(dup.kind, SceneErrorKind::DuplicateControl);
  EXPECT_EQ(dup.field, "objects[0].controls[1].node");
  EXPECT_EQ(
      springSceneErrorOf(mesh("[[0, 1, 1]]", R"(, "controls": [{"node": 5, "displacement": [0,0,1]}])")).kind,
      SceneErrorKind::IndexOutOfRange);
  EXPECT_EQ(springSceneErrorOf(mesh("[[0, 1, 1]]", R"(, "controls": [{"node": 1}])")).field,
            "objects[0].controls[0].displacement");
  EXPECT_EQ(springSceneErrorOf(mesh("[[0, 1, 1]]",
                         R"(, "fixed": [1], "controls": [{"node": 1, "displacement": [0,0,1]}])"))
                .kind,
            SceneErrorKind::InvalidValue);
  EXPECT_EQ(springSceneErrorOf(mesh("[[0, 1, 1]]",
                         R"(, "controls": [{"node": 1, "displacement": [0,0,1], "force": 2}])"))
                .field,
            "objects[0].controls[0].force");
  // the same local index in two objects is two different nodes
  const SceneLoad two = parseSpringScene(
      R"({"objects": [{"type": "lattice", "size": [2,2,2], "controls": [{"node": 7, "displacement": [0,0,1]}]},
                      {"type": "lattice", "size": [2,2,2], "controls": [{"node": 7, "displacement": [0,0,1]}]}]})");
  ASSERT_TRUE(std::holds_alternative<SpringScene>(two));
  EXPECT_EQ(sceneOf(two).controls.nodes, (std::vector<int>{7, 15}));
}

TEST(SpringScene, SurfaceMeshFailureCarriesTheImporterError) {
  const SceneLoad r = parseSpringScene(
      R"({"objects": [{"type": "surface-mesh", "file": "nowhere.obj"}]})", "s.json", kTestScenes);
  ASSERT_TRUE(std::holds_alternative<SceneError>(r));
  const SceneError& e = std::get<SceneError>(r);
  EXPECT_EQ(e.kind, SceneErrorKind::MeshImport);
  EXPECT_EQ(e.field, "objects[0].file");
  ASSERT_TRUE(e.meshError.has_value());
  EXPECT_EQ(e.meshError->kind, MeshImportErrorKind::FileNotFound);
}

TEST(SpringScene, LocateJsonPath) {
  const std::string text = R"({"a": [1, {"b": "x\"y", "c": [[], [5]]}], "d": {}})";
  EXPECT_EQ(locateJsonPath(text, ""), 0u);
  EXPECT_EQ(locateJsonPath(text, "a"), text.find('['));
  EXPECT_EQ(locateJsonPath(text, "a[1].c[1][0]"), text.find('5'));
  EXPECT_EQ(locateJsonPath(text, "d"), text.rfind('{'));
  EXPECT_FALSE(locateJsonPath(text, "a[2]").has_value());
  EXPECT_EQ(lineColumnAt("ab\ncd", 4), std::make_pair(2, 2));
}

}  // namespace
}  // namespace microsim::sim
