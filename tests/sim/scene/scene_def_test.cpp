#include "microsim/sim/scene/scene_def.h"

#include <gtest/gtest.h>

#include <string>
#include <variant>

namespace microsim::sim {
namespace {

const std::string kShippedScenes = std::string(MICROSIM_SOURCE_DIR) + "/resources/scenes/";
const std::string kMeshes = std::string(MICROSIM_SOURCE_DIR) + "/resources/meshes";

SceneError sceneDefErrorOf(const std::string& text) {
  SceneDefLoad load = parseSceneDef(text, "test.json", kMeshes);
  EXPECT_TRUE(std::holds_alternative<SceneError>(load));
  return std::holds_alternative<SceneError>(load) ? std::get<SceneError>(load) : SceneError{};
}

TEST(SceneDef, EveryShippedSceneLoads) {
  for (const char* name : {"anastomosis.json", "fine_anastomosis.json", "single_vessel.json",
                           "lattice.json", "spring_mesh.json", "instrument_tie.json"}) {
    SceneDefLoad load = loadSceneDef(kShippedScenes + name);
    if (auto* e = std::get_if<SceneError>(&load))
      ADD_FAILURE() << name << ": kind " << int(e->kind) << " at " << e->line << ":" << e->column
                    << " field " << e->field;
  }
}

TEST(SceneDef, TheAnastomosisSceneHasTwoVesselEndsTwoForcepsAndANeedle) {
  SceneDefLoad load = loadSceneDef(kShippedScenes + "anastomosis.json");
  ASSERT_TRUE(std::holds_alternative<SceneDef>(load));
  const SceneDef& s = std::get<SceneDef>(load);
  ASSERT_EQ(s.vessels.size(), 2u);
  EXPECT_EQ(s.vessels[0].end, 0);
  EXPECT_EQ(s.vessels[1].end, 1);
  EXPECT_EQ(s.tissue.model.nodeCount(), 2 * 2 * 7 * 16);
  EXPECT_EQ(s.vessels[1].firstNode, 2 * 7 * 16);
  // the cut ends face each other across the 0.5 mm gap
  const Vec3 cutA = s.vessels[0].def.origin + s.vessels[0].def.length * s.vessels[0].def.direction;
  const Vec3 cutB = s.vessels[1].def.origin + s.vessels[1].def.length * s.vessels[1].def.direction;
  EXPECT_NEAR((cutB - cutA).norm(), 0.5, 1e-12);
  EXPECT_NEAR(cutA.x(), -0.25, 1e-12);
  ASSERT_TRUE(s.forceps[0] && s.forceps[1]);
  EXPECT_EQ(s.forceps[0]->jawTriangles.size(), 12u);
  ASSERT_TRUE(s.needle.has_value());
  EXPECT_EQ(s.needle->suture.links, 60);
  EXPECT_FALSE(s.scalpel.has_value());
  EXPECT_EQ(s.tree, CollisionTree::Aabb);
  EXPECT_EQ(s.solver.name, "newton");
  EXPECT_EQ(s.step.rateHz, 100.0);
  // a wall material, and the tissue limits on
  ASSERT_TRUE(s.vessels[0].def.material.has_value());
  EXPECT_EQ(s.vessels[0].def.material->youngsModulus, 3.0e5);
  EXPECT_EQ(s.tissue.model.link(0).law, StiffnessLaw::Exponential);
  EXPECT_EQ(s.limits.overstretch, 0.3);
  EXPECT_EQ(s.limits.tear, 0.6);
}

TEST(SceneDef, TheThreadsBreakingStretchesAreRead) {
  SceneDefLoad load = parseSceneDef(
      R"({"objects": [{"type": "severed-vessel"}], "tools": {"needle": {"break_stretch": 0.04, "knot_break_stretch": 0.15}}})");
  ASSERT_TRUE(std::holds_alternative<SceneDef>(load));
  const SceneDef& s = std::get<SceneDef>(load);
  ASSERT_TRUE(s.needle.has_value());
  EXPECT_EQ(s.needle->suture.breakStretch, 0.04);
  EXPECT_EQ(s.needle->suture.knotBreakStretch, 0.15);
  // unset: a knot breaks at twice the grips' stretch (knot_strain.h)
  const SceneDefLoad plain = parseSceneDef(R"({"objects": [{"type": "severed-vessel"}], "tools": {"needle": {}}})");
  ASSERT_TRUE(std::holds_alternative<SceneDef>(plain));
  EXPECT_EQ(std::get<SceneDef>(plain).needle->suture.knotBreakStretch, 0.10);
}

TEST(SceneDef, AVesselMaterialIsReadAndAnExplicitStiffnessWins) {
  SceneDefLoad load = parseSceneDef(R"({"objects": [{"type": "severed-vessel", "k_between": 80,
      "material": {"youngs_modulus": 2e5, "fung_exponent": 7}}]})");
  ASSERT_TRUE(std::holds_alternative<SceneDef>(load));
  const SceneDef& s = std::get<SceneDef>(load);
  const WallMaterial& m = *s.vessels[1].def.material;
  EXPECT_EQ(m.youngsModulus, 2e5);
  EXPECT_EQ(m.fungExponent, 7.0);
  EXPECT_EQ(m.density, WallMaterial{}.density);
  bool between = false;
  for (const Link& l : s.tissue.model.links()) {
    EXPECT_EQ(l.law, StiffnessLaw::Exponential);
    EXPECT_EQ(l.gain, 7.0);
    between = between || l.k == 80.0;
  }
  EXPECT_TRUE(between);
  // the same on a single vessel, through the spring-scene loader
  load = parseSceneDef(R"({"objects": [{"type": "vessel", "material": {}}]})");
  ASSERT_TRUE(std::holds_alternative<SceneDef>(load));
  EXPECT_EQ(std::get<SceneDef>(load).tissue.model.link(0).law, StiffnessLaw::Exponential);
  EXPECT_NEAR(std::get<SceneDef>(load).tissue.model.mass(0), 1.06e-3 * 0.09 * 3.0 * 3.14159265358979 / 98, 1e-12);
}

TEST(SceneDef, BadMaterialsAreRejectedByField) {
  EXPECT_EQ(sceneDefErrorOf(R"({"objects": [{"type": "severed-vessel", "material": {"youngs_modulus": 0}}]})").field,
            "objects[0].material.youngs_modulus");
  EXPECT_EQ(sceneDefErrorOf(R"({"objects": [{"type": "vessel", "material": {"fung_exponent": 80}}]})").field,
            "objects[0].material.fung_exponent");
  const SceneError e = sceneDefErrorOf(R"({"objects": [{"type": "vessel", "material": {"modulus": 1}}]})");
  EXPECT_EQ(e.kind, SceneErrorKind::UnknownField);
}

TEST(SceneDef, OnlyDeclaredToolsExist) {
  SceneDefLoad load = parseSceneDef(R"({"objects": [{"type": "lattice", "size": [2, 2, 2]}]})");
  ASSERT_TRUE(std::holds_alternative<SceneDef>(load));
  const SceneDef& s = std::get<SceneDef>(load);
  EXPECT_FALSE(s.forceps[0] || s.forceps[1] || s.needle || s.scalpel);
  EXPECT_TRUE(s.vessels.empty());
}

TEST(SceneDef, MalformedJsonNamesLineAndColumn) {
  const SceneError e = sceneDefErrorOf("{\n  \"objects\": [\n    {\"type\": \"lattice\",, }\n  ]\n}");
  EXPECT_EQ(e.kind, SceneErrorKind::MalformedJson);
  EXPECT_EQ(e.file, "test.json");
  EXPECT_EQ(e.line, 3);
  EXPECT_EQ(e.column, 24);
}

TEST(SceneDef, AnUnknownToolFieldIsNamedWithItsPosition) {
  const SceneError e = sceneDefErrorOf(
      "{\"objects\": [{\"type\": \"lattice\", \"size\": [2, 2, 2]}],\n"
      " \"tools\": {\"forceps\": [\n"
      "   {\"hand\": \"left\", \"mesh\": \"forceps_jaw.obj\", \"colour\": 1}]}}");
  EXPECT_EQ(e.kind, SceneErrorKind::UnknownField);
  EXPECT_EQ(e.field, "tools.forceps[0].colour");
  EXPECT_EQ(e.line, 3);
  EXPECT_EQ(e.column, 58);
}

TEST(SceneDef, AForcepsHoldStiffnessIsReadAndARadiusOfGrabIsNoLongerAField) {
  const auto forceps = [](const std::string& fields) {
    return R"({"objects": [{"type": "lattice", "size": [2, 2, 2]}], "tools": {"forceps": [
      {"hand": "right", "mesh": "forceps_jaw.obj")" + fields + "}]}}";
  };
  SceneDefLoad load = parseSceneDef(forceps(""), "test.json", kMeshes);
  ASSERT_TRUE(std::holds_alternative<SceneDef>(load));
  EXPECT_EQ(std::get<SceneDef>(load).forceps[1]->holdStiffness, 3e5);
  load = parseSceneDef(forceps(R"(, "hold_stiffness": 5e4)"), "test.json", kMeshes);
  ASSERT_TRUE(std::holds_alternative<SceneDef>(load));
  EXPECT_EQ(std::get<SceneDef>(load).forceps[1]->holdStiffness, 5e4);
  EXPECT_EQ(sceneDefErrorOf(forceps(R"(, "hold_stiffness": 0)")).field, "tools.forceps[0].hold_stiffness");
  // the grasp is the jaws' geometry (tools/jaw_grasp.h), not a radius around their tips
  EXPECT_EQ(sceneDefErrorOf(forceps(R"(, "grab_radius": 0.08)")).field, "tools.forceps[0].grab_radius");
}

TEST(SceneDef, AMissingJawMeshIsAMeshImportError) {
  const SceneError e = sceneDefErrorOf(
      "{\"objects\": [{\"type\": \"lattice\", \"size\": [2, 2, 2]}],\n"
      " \"tools\": {\"forceps\": [{\"hand\": \"right\", \"mesh\": \"no_such_jaw.obj\"}]}}");
  EXPECT_EQ(e.kind, SceneErrorKind::MeshImport);
  EXPECT_EQ(e.field, "tools.forceps[0].mesh");
  ASSERT_TRUE(e.meshError.has_value());
  EXPECT_EQ(e.meshError->kind, MeshImportErrorKind::FileNotFound);
  EXPECT_EQ(e.line, 2);
}

TEST(SceneDef, ObjectErrorsFromTheSpringSceneLoaderPointIntoThisFile) {
  const SceneError e = sceneDefErrorOf(
      "{\"objects\": [\n"
      "  {\"type\": \"lattice\", \"size\": [2, 2, 2]},\n"
      "  {\"type\": \"spring-mesh\", \"nodes\": [[0,0,0], [1,0,0]], \"links\": [[0, 7, 5]]}]}");
  EXPECT_EQ(e.kind, SceneErrorKind::IndexOutOfRange);
  EXPECT_EQ(e.field, "objects[1].links[0][1]");
  EXPECT_EQ(e.line, 3);
  EXPECT_EQ(e.column, 70);
}

TEST(SceneDef, BadValuesAreRejectedByField) {
  struct Case {
    const char* text;
    SceneErrorKind kind;
    const char* field;
  };
  const Case cases[] = {
      {R"({"version": 2, "objects": [{"type": "lattice", "size": [2,2,2]}]})",
       SceneErrorKind::InvalidValue, "version"},
      {R"({"objects": []})", SceneErrorKind::InvalidValue, "objects"},
      {R"({"objects": [{"type": "severed-vessel", "gap": -1}]})", SceneErrorKind::NegativeValue,
       "objects[0].gap"},
      {R"({"objects": [{"type": "severed-vessel", "radius": 0.1, "wall_thickness": 0.2}]})",
       SceneErrorKind::InvalidValue, "objects[0].wall_thickness"},
      {R"({"objects": [{"type": "severed-vessel"}], "solver": {"name": "magic"}})",
       SceneErrorKind::InvalidValue, "solver.name"},
      {R"({"objects": [{"type": "severed-vessel"}], "tools": {"needle": {"links": 3}}})",
       SceneErrorKind::InvalidValue, "tools.needle.links"},
      {R"({"objects": [{"type": "severed-vessel"}], "tools": {"needle": {"rotation": [0,0,0,0]}}})",
       SceneErrorKind::InvalidValue, "tools.needle.rotation"},
      {R"({"objects": [{"type": "severed-vessel"}], "tools": {"scissors": {"opening_deg": 90}}})",
       SceneErrorKind::InvalidValue, "tools.scissors.opening_deg"},
      {R"({"objects": [{"type": "severed-vessel"}], "tools": {"scissors": {"cut_at": 1.5}}})",
       SceneErrorKind::InvalidValue, "tools.scissors.cut_at"},
      {R"({"objects": [{"type": "severed-vessel"}], "tools": {"needle": {"min_tie_length": -1}}})",
       SceneErrorKind::NegativeValue, "tools.needle.min_tie_length"},
      {R"({"objects": [{"type": "severed-vessel"}], "tools": {"needle": {"knot_break_stretch": 0}}})",
       SceneErrorKind::InvalidValue, "tools.needle.knot_break_stretch"},
      {R"({"objects": [{"type": "severed-vessel"}], "tools": {"needle": {"knot_break_stretch": "10 %"}}})",
       SceneErrorKind::WrongType, "tools.needle.knot_break_stretch"},
      {R"({"objects": [{"type": "severed-vessel"}], "step": {"rate_hz": 0}})",
       SceneErrorKind::InvalidValue, "step.rate_hz"},
      {R"({"objects": [{"type": "severed-vessel"}], "surface": {"subdivision": 5}})",
       SceneErrorKind::InvalidValue, "surface.subdivision"},
      {R"({"objects": [{"type": "severed-vessel"}], "surface": {"subdivision": "smooth"}})",
       SceneErrorKind::WrongType, "surface.subdivision"},
      {R"({"objects": [{"type": "severed-vessel"}], "collision": {"tree": "kd"}})",
       SceneErrorKind::InvalidValue, "collision.tree"},
      {R"({"objects": [{"type": "severed-vessel"}], "camera": {"eye": [0, 0, 1e999]}})",
       SceneErrorKind::NonFinite, "camera.eye[2]"},
      {R"({"objects": [{"type": "teapot"}]})", SceneErrorKind::UnknownObjectType,
       "objects[0].type"},
  };
  for (const Case& c : cases) {
    const SceneError e = sceneDefErrorOf(c.text);
    EXPECT_EQ(e.kind, c.kind) << c.text;
    EXPECT_EQ(e.field, c.field) << c.text;
  }
}

}  // namespace
}  // namespace microsim::sim
