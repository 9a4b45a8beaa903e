#include "microsim/sim/scene/scene_def.h"

#include "microsim/sim/mesh/smooth_surface.h"

#include "microsim/sim/mesh/merge.h"
#include "microsim/sim/mesh/surface_import.h"
#include "scene/scene_json_reader.h"

#include <nlohmann/json.hpp>

#include <exception>
#include <filesystem>
#include <utility>

namespace microsim::sim {

namespace {

using json = nlohmann::json;
using detail::JsonReader;

TriangleRange shifted(TriangleRange r, int by) { return {r.begin + by, r.end + by}; }

class SceneReader : public JsonReader {
 public:
  SceneReader(std::string file, std::string baseDir)
      : file_(std::move(file)), baseDir_(std::move(baseDir)) {}

  bool scene(const json& doc, SceneDef& out);

 private:
  bool objects(const json& list, SceneDef& out);
  bool delegated(const json& o, std::size_t i, SceneDef& out);
  bool vesselFields(const json& o, const std::string& path, VesselDef& def);
  bool severedVessel(const json& o, std::size_t i, SceneDef& out);
  void addVessel(SceneDef& out, const VesselMesh& mesh, int object, int end, int offset,
                 int firstTriangle);
  bool solver(const json& v, TissueSolverDef& out);
  bool forceps(const json& v, const std::string& path, SceneDef& out);
  bool needle(const json& v, const std::string& path, NeedleDef& out);
  bool scalpel(const json& v, const std::string& path, ScalpelDef& out);
  bool scissors(const json& v, const std::string& path, ScissorsDef& out);
  bool camera(const json& v, CameraDef& out);
  bool step(const json& v, StepDef& out);
  bool surface(const json& v, SurfaceDef& out);
  bool limits(const json& v, TissueLimitsDef& out);

  std::string file_;
  std::string baseDir_;
};

// one spring-scene object through the spring-scene loader, errors mapped back to this file
bool SceneReader::delegated(const json& o, std::size_t i, SceneDef& out) {
  const json doc = {{"objects", json::array({o})}};
  SceneLoad load = parseSpringScene(doc.dump(), file_, baseDir_);
  if (auto* e = std::get_if<SceneError>(&load)) {
    const std::string inner = "objects[0]";
    std::string field = e->field;
    if (field.rfind(inner, 0) == 0) field = index("objects", i) + field.substr(inner.size());
    fail(e->kind, field);
    error()->meshError = e->meshError;
    return false;
  }
  SpringScene& part = std::get<SpringScene>(load);
  SceneObject info = part.objects.front();
  SpringModel& model = out.tissue.model;
  info.firstNode = model.nodeCount();
  info.firstLink = model.linkCount();
  info.firstTriangle = static_cast<int>(model.triangles().size());
  const int offset = appendModel(model, part.model);
  for (int c = 0; c < part.controls.size(); ++c)
    out.tissue.controls.add(offset + part.controls.nodes[static_cast<std::size_t>(c)],
                            part.controls.targets.col(c));
  out.tissue.objects.push_back(info);

  // a vessel keeps its per-node layout for the needle's pierce events
  if (info.type == "vessel") {
    VesselDef def;
    if (!vesselFields(o, index("objects", i), def)) return false;
    if (const json* v = field(o, "origin")) vec3(*v, "", def.origin);
    if (const json* v = field(o, "direction")) vec3(*v, "", def.direction);
    addVessel(out, vessel(def), static_cast<int>(out.tissue.objects.size()) - 1, -1, offset,
              info.firstTriangle);
  }
  return true;
}

bool SceneReader::vesselFields(const json& o, const std::string& path, VesselDef& def) {
  if (const json* v = field(o, "preset")) {
    std::string preset;
    if (!string(*v, key(path, "preset"), preset)) return false;
    if (preset == "fine")
      def = VesselDef::fine();
    else if (preset != "paper")
      return fail(SceneErrorKind::InvalidValue, key(path, "preset"));
  }
  if (!optPositive(o, path, "radius", def.radius) ||
      !optPositive(o, path, "wall_thickness", def.wallThickness) ||
      !optPositive(o, path, "length", def.length) || !optPositive(o, path, "mass", def.mass) ||
      !optNonNegative(o, path, "k_layer", def.kLayer) ||
      !optNonNegative(o, path, "k_between", def.kBetween) ||
      !optNonNegative(o, path, "damping", def.damping) ||
      !optInt(o, path, "rings", 2, def.rings) ||
      !optInt(o, path, "nodes_per_ring", 3, def.nodesPerRing) ||
      !optBool(o, path, "clamp_first_ring", def.clampFirstRing) || !wallMaterial(o, path, def))
    return false;
  if (def.wallThickness >= def.radius)
    return fail(SceneErrorKind::InvalidValue, key(path, "wall_thickness"));
  if (2LL * def.rings * def.nodesPerRing > 8'000'000) return fail(SceneErrorKind::InvalidValue, path);
  return true;
}

void SceneReader::addVessel(SceneDef& out, const VesselMesh& mesh, int object, int end,
                            int offset, int firstTriangle) {
  SceneVessel v;
  v.object = object;
  v.end = end;
  v.def = mesh.def;
  v.def.direction = mesh.def.direction.normalized();
  v.firstNode = offset;
  v.firstTriangle = firstTriangle;
  v.outerSurface = shifted(mesh.outerSurface, firstTriangle);
  v.innerSurface = shifted(mesh.innerSurface, firstTriangle);
  v.clampedEnd = shifted(mesh.clampedEnd, firstTriangle);
  v.cutEnd = shifted(mesh.cutEnd, firstTriangle);
  out.vessels.push_back(v);
}

bool SceneReader::severedVessel(const json& o, std::size_t i, SceneDef& out) {
  const std::string path = index("objects", i);
  if (!object(o, path,
              {"type", "name", "gap", "center", "axis", "preset", "radius", "wall_thickness",
               "length", "rings", "nodes_per_ring", "k_layer", "k_between", "mass", "damping",
               "clamp_first_ring", "material"}))
    return false;
  VesselDef def;
  double gap = 0.5;
  Vec3 center = Vec3::Zero();
  Vec3 axis = Vec3::UnitX();
  if (!vesselFields(o, path, def) || !optNonNegative(o, path, "gap", gap) ||
      !optVec3(o, path, "center", center) || !optVec3(o, path, "axis", axis))
    return false;
  if (!(axis.norm() > 0.0)) return fail(SceneErrorKind::InvalidValue, key(path, "axis"));
  axis.normalize();
  SceneObject info;
  info.type = "severed-vessel";
  if (const json* n = field(o, "name") ; n && !string(*n, key(path, "name"), info.name))
    return false;

  // end 0 runs from its clamp towards +axis, end 1 from its clamp towards −axis
  SpringModel& model = out.tissue.model;
  info.firstNode = model.nodeCount();
  info.firstLink = model.linkCount();
  info.firstTriangle = static_cast<int>(model.triangles().size());
  const int object = static_cast<int>(out.tissue.objects.size());
  for (int end = 0; end < 2; ++end) {
    VesselDef d = def;
    const double sign = end == 0 ? -1.0 : 1.0;
    d.origin = center + sign * (0.5 * gap + def.length) * axis;
    d.direction = -sign * axis;
    const VesselMesh mesh = vessel(d);
    const int firstTriangle = static_cast<int>(model.triangles().size());
    const int offset = appendModel(model, mesh.model);
    addVessel(out, mesh, object, end, offset, firstTriangle);
  }
  info.nodeCount = model.nodeCount() - info.firstNode;
  info.linkCount = model.linkCount() - info.firstLink;
  info.triangleCount = static_cast<int>(model.triangles().size()) - info.firstTriangle;
  out.tissue.objects.push_back(info);
  return true;
}

bool SceneReader::objects(const json& list, SceneDef& out) {
  if (!list.is_array()) return fail(SceneErrorKind::WrongType, "objects");
  if (list.empty()) return fail(SceneErrorKind::InvalidValue, "objects");
  for (std::size_t i = 0; i < list.size(); ++i) {
    const json& o = list[i];
    const std::string path = index("objects", i);
    if (!o.is_object()) return fail(SceneErrorKind::WrongType, path);
    const json* type = field(o, "type");
    const bool severed = type && type->is_string() && type->get<std::string>() == "severed-vessel";
    if (!(severed ? severedVessel(o, i, out) : delegated(o, i, out))) return false;
  }
  return true;
}

bool SceneReader::solver(const json& v, TissueSolverDef& out) {
  const std::string path = "solver";
  if (!object(v, path,
              {"name", "iterations", "tolerance", "alpha", "relaxation", "cutout", "momentum",
               "damping", "active_region", "linear_tolerance"}))
    return false;
  if (const json* f = field(v, "name")) {
    if (!string(*f, key(path, "name"), out.name)) return false;
    if (!makeSolver(out.name)) return fail(SceneErrorKind::InvalidValue, key(path, "name"));
  }
  SolverParams& p = out.params;
  if (!optInt(v, path, "iterations", 1, out.iterations) ||
      !optNonNegative(v, path, "tolerance", out.tolerance) ||
      !optNonNegative(v, path, "alpha", p.alpha) ||
      !optPositive(v, path, "relaxation", p.relaxation) ||
      !optNonNegative(v, path, "cutout", p.cutout) ||
      !optNonNegative(v, path, "momentum", p.momentum) ||
      !optNonNegative(v, path, "damping", p.damping) ||
      !optBool(v, path, "active_region", p.activeRegion) ||
      !optNonNegative(v, path, "linear_tolerance", p.linearTolerance))
    return false;
  if (p.momentum >= 1.0) return fail(SceneErrorKind::InvalidValue, key(path, "momentum"));
  if (p.relaxation >= 2.0) return fail(SceneErrorKind::InvalidValue, key(path, "relaxation"));
  return true;
}

bool SceneReader::forceps(const json& v, const std::string& path, SceneDef& out) {
  if (!object(v, path, {"hand", "mesh", "scale", "opening_deg", "hold_stiffness", "close_at"}))
    return false;
  ForcepsDef def;
  const json* hand = nullptr;
  std::string handName;
  if (!required(v, path, "hand", hand) || !string(*hand, key(path, "hand"), handName)) return false;
  if (handName == "left")
    def.hand = Hand::Left;
  else if (handName == "right")
    def.hand = Hand::Right;
  else
    return fail(SceneErrorKind::InvalidValue, key(path, "hand"));
  if (out.forceps[static_cast<std::size_t>(def.hand)])
    return fail(SceneErrorKind::InvalidValue, key(path, "hand"));
  SurfaceMeshOptions options;
  if (!optPositive(v, path, "scale", options.scale) ||
      !optPositive(v, path, "opening_deg", def.openingDeg) ||
      !optPositive(v, path, "hold_stiffness", def.holdStiffness) ||
      !optPositive(v, path, "close_at", def.closeAt))
    return false;
  if (def.openingDeg >= 90.0) return fail(SceneErrorKind::InvalidValue, key(path, "opening_deg"));
  if (def.closeAt > 1.0) return fail(SceneErrorKind::InvalidValue, key(path, "close_at"));

  // the jaw mesh, relative to the scene file
  const json* mesh = nullptr;
  std::string file;
  if (!required(v, path, "mesh", mesh) || !string(*mesh, key(path, "mesh"), file)) return false;
  std::filesystem::path p = file;
  if (p.is_relative()) p = std::filesystem::path(baseDir_) / p;
  def.meshFile = p.string();
  SurfaceImport imported = importSurfaceMesh(def.meshFile, options);
  if (auto* e = std::get_if<MeshImportError>(&imported)) {
    fail(SceneErrorKind::MeshImport, key(path, "mesh"));
    error()->meshError = *e;
    return false;
  }
  const SpringModel& jaw = std::get<SpringModel>(imported);
  def.jawVertices = jaw.restPositions();
  def.jawTriangles = jaw.triangles();
  out.forceps[static_cast<std::size_t>(def.hand)] = std::move(def);
  return true;
}

bool SceneReader::needle(const json& v, const std::string& path, NeedleDef& out) {
  if (!object(v, path,
              {"shape", "radius", "length", "thread_length", "links", "needle_links",
               "break_stretch", "knot_break_stretch", "contact_radius", "friction", "drag", "position", "rotation",
               "solver", "substeps", "iterations", "coupling_gain", "coupling_stiffness", "puncture_force",
               "min_tie_length", "stay_stitch"}))
    return false;
  suture::SutureDef& s = out.suture;
  s.links = 60;
  s.length = 8.0;
  s.needleRadius = 0.8;
  if (const json* f = field(v, "shape")) {
    std::string shape;
    if (!string(*f, key(path, "shape"), shape)) return false;
    if (shape == "curved")
      s.needleShape = suture::NeedleShape::Curved;
    else if (shape == "straight")
      s.needleShape = suture::NeedleShape::Straight;
    else
      return fail(SceneErrorKind::InvalidValue, key(path, "shape"));
  }
  if (!optPositive(v, path, "radius", s.needleRadius) ||
      !optPositive(v, path, "length", s.needleLength) ||
      !optPositive(v, path, "thread_length", s.length) || !optInt(v, path, "links", 2, s.links) ||
      !optInt(v, path, "needle_links", 1, s.needleLinks) ||
      !optPositive(v, path, "break_stretch", s.breakStretch) ||
      !optPositive(v, path, "knot_break_stretch", s.knotBreakStretch) ||
      !optPositive(v, path, "contact_radius", s.contactRadius) ||
      !optNonNegative(v, path, "friction", s.friction) ||
      !optNonNegative(v, path, "drag", s.drag) ||
      !optInt(v, path, "substeps", 1, out.step.substeps) ||
      !optInt(v, path, "iterations", 1, out.step.iterations) ||
      !optPositive(v, path, "coupling_gain", out.coupling.gain) ||
      !optPositive(v, path, "coupling_stiffness", out.coupling.stiffness) ||
      !optNonNegative(v, path, "puncture_force", out.punctureForce) ||
      !optNonNegative(v, path, "min_tie_length", out.minTieLength))
    return false;
  if (s.links < s.needleLinks + 1) return fail(SceneErrorKind::InvalidValue, key(path, "links"));
  if (out.coupling.gain > 1.0) return fail(SceneErrorKind::InvalidValue, key(path, "coupling_gain"));
  if (!suture::validSutureDef(s)) return fail(SceneErrorKind::InvalidValue, path);
  if (const json* f = field(v, "solver")) {
    if (!string(*f, key(path, "solver"), out.solver)) return false;
    if (!suture::makeSutureSolver(out.solver))
      return fail(SceneErrorKind::InvalidValue, key(path, "solver"));
  }

  if (const json* f = field(v, "stay_stitch")) {
    const std::string sp = key(path, "stay_stitch");
    StayStitchDef stitch;
    if (!object(*f, sp, {"angle_deg", "bite_walls", "tail_mm"}) ||
        !optNumber(*f, sp, "angle_deg", stitch.angleDeg) || !optPositive(*f, sp, "bite_walls", stitch.biteWalls) ||
        !optPositive(*f, sp, "tail_mm", stitch.tailMm))
      return false;
    out.stayStitch = stitch;
  }

  // the needle's pose at the start
  Vec3 position = Vec3::Zero();
  if (!optVec3(v, path, "position", position)) return false;
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  if (const json* f = field(v, "rotation")) {
    const std::string rp = key(path, "rotation");
    if (!f->is_array() || f->size() != 4) return fail(SceneErrorKind::WrongType, rp);
    double c[4];
    for (std::size_t k = 0; k < 4; ++k)
      if (!number((*f)[k], index(rp, k), c[k])) return false;
    q = Eigen::Quaterniond(c[0], c[1], c[2], c[3]);
    if (!(q.norm() > 1e-12)) return fail(SceneErrorKind::InvalidValue, rp);
    q.normalize();
  }
  out.pose = Eigen::Isometry3d::Identity();
  out.pose.linear() = q.toRotationMatrix();
  out.pose.translation() = position;
  return true;
}

bool SceneReader::scalpel(const json& v, const std::string& path, ScalpelDef& out) {
  return object(v, path, {"blade_length", "blade_height"}) &&
         optPositive(v, path, "blade_length", out.bladeLength) &&
         optPositive(v, path, "blade_height", out.bladeHeight);
}

bool SceneReader::scissors(const json& v, const std::string& path, ScissorsDef& out) {
  if (!object(v, path, {"blade_length", "opening_deg", "blade_half_thickness", "cut_at"}) ||
      !optPositive(v, path, "blade_length", out.bladeLength) ||
      !optPositive(v, path, "opening_deg", out.openingDeg) ||
      !optNonNegative(v, path, "blade_half_thickness", out.bladeHalfThickness) ||
      !optPositive(v, path, "cut_at", out.cutAt))
    return false;
  if (out.openingDeg >= 90.0) return fail(SceneErrorKind::InvalidValue, key(path, "opening_deg"));
  if (out.cutAt > 1.0) return fail(SceneErrorKind::InvalidValue, key(path, "cut_at"));
  return true;
}

bool SceneReader::camera(const json& v, CameraDef& out) {
  const std::string path = "camera";
  if (!object(v, path, {"eye", "target", "up", "fov_deg"}) || !optVec3(v, path, "eye", out.eye) ||
      !optVec3(v, path, "target", out.target) || !optVec3(v, path, "up", out.up) ||
      !optPositive(v, path, "fov_deg", out.fovDeg))
    return false;
  if (out.fovDeg >= 180.0) return fail(SceneErrorKind::InvalidValue, key(path, "fov_deg"));
  if ((out.eye - out.target).norm() == 0.0) return fail(SceneErrorKind::InvalidValue, key(path, "eye"));
  if (out.up.cross(out.eye - out.target).norm() == 0.0)
    return fail(SceneErrorKind::InvalidValue, key(path, "up"));
  return true;
}

bool SceneReader::step(const json& v, StepDef& out) {
  const std::string path = "step";
  return object(v, path, {"rate_hz", "budget_ms"}) && optPositive(v, path, "rate_hz", out.rateHz) &&
         optPositive(v, path, "budget_ms", out.budgetMs);
}

bool SceneReader::surface(const json& v, SurfaceDef& out) {
  const std::string path = "surface";
  if (!object(v, path, {"subdivision"}) || !optInt(v, path, "subdivision", 0, out.subdivision))
    return false;
  if (out.subdivision > kMaxSmoothLevels)
    return fail(SceneErrorKind::InvalidValue, key(path, "subdivision"));
  return true;
}

bool SceneReader::limits(const json& v, TissueLimitsDef& out) {
  const std::string path = "tissue";
  return object(v, path, {"overstretch", "tear"}) &&
         optNonNegative(v, path, "overstretch", out.overstretch) &&
         optNonNegative(v, path, "tear", out.tear);
}

bool SceneReader::scene(const json& doc, SceneDef& out) {
  if (!object(doc, "",
              {"version", "objects", "gravity", "solver", "tools", "camera", "step", "surface",
               "tissue", "collision"}))
    return false;
  if (const json* v = field(doc, "version")) {
    int version = 0;
    if (!intAtLeast(*v, "version", 1, version)) return false;
    if (version != kSceneFileVersion) return fail(SceneErrorKind::InvalidValue, "version");
  }
  const json* list = nullptr;
  if (!required(doc, "", "objects", list) || !objects(*list, out)) return false;
  if (!optVec3(doc, "", "gravity", out.tissue.model.gravity)) return false;
  if (const json* v = field(doc, "solver"); v && !solver(*v, out.solver)) return false;
  if (const json* v = field(doc, "camera"); v && !camera(*v, out.camera)) return false;
  if (const json* v = field(doc, "step"); v && !step(*v, out.step)) return false;
  if (const json* v = field(doc, "surface"); v && !surface(*v, out.surface)) return false;
  if (const json* v = field(doc, "tissue"); v && !limits(*v, out.limits)) return false;
  if (const json* v = field(doc, "collision")) {
    std::string tree = "aabb";
    if (!object(*v, "collision", {"tree", "tissue", "tools", "stiffness", "thickness", "reach", "self_distance"}))
      return false;
    if (const json* t = field(*v, "tree"); t && !string(*t, "collision.tree", tree)) return false;
    ContactDef& c = out.contact;
    if (!optBool(*v, "collision", "tissue", c.tissue) || !optBool(*v, "collision", "tools", c.tools) ||
        !optPositive(*v, "collision", "stiffness", c.params.stiffness) ||
        !optPositive(*v, "collision", "thickness", c.params.thickness) ||
        !optPositive(*v, "collision", "reach", c.params.reach) ||
        !optNonNegative(*v, "collision", "self_distance", c.params.selfDistance))
      return false;
    if (tree == "aabb")
      out.tree = CollisionTree::Aabb;
    else if (tree == "sphere")
      out.tree = CollisionTree::Sphere;
    else
      return fail(SceneErrorKind::InvalidValue, "collision.tree");
  }

  // tools: only what is declared exists
  if (const json* tools = field(doc, "tools")) {
    if (!object(*tools, "tools", {"forceps", "needle", "scalpel", "scissors"})) return false;
    if (const json* list = field(*tools, "forceps")) {
      if (!list->is_array() || list->size() > static_cast<std::size_t>(kHandCount))
        return fail(SceneErrorKind::WrongType, "tools.forceps");
      for (std::size_t i = 0; i < list->size(); ++i)
        if (!forceps((*list)[i], index("tools.forceps", i), out)) return false;
    }
    if (const json* v = field(*tools, "needle")) {
      NeedleDef def;
      if (!needle(*v, "tools.needle", def)) return false;
      out.needle = std::move(def);
    }
    if (const json* v = field(*tools, "scalpel")) {
      ScalpelDef def;
      if (!scalpel(*v, "tools.scalpel", def)) return false;
      out.scalpel = def;
    }
    if (const json* v = field(*tools, "scissors")) {
      ScissorsDef def;
      if (!scissors(*v, "tools.scissors", def)) return false;
      out.scissors = def;
    }
  }
  out.tissue.model.finalize();

  // a stitch already placed: its thread laid once the vessels are built
  if (out.needle && out.needle->stayStitch) {
    const auto laid = layStayStitch(out, *out.needle->stayStitch);
    if (!std::holds_alternative<LaidStayStitch>(laid))
      return fail(SceneErrorKind::InvalidValue, "tools.needle.stay_stitch");
    out.needle->initialShape = std::get<LaidStayStitch>(laid).shape;
    out.needle->initialPierces = std::get<LaidStayStitch>(laid).pierces;
  }
  return true;
}

}  // namespace

SceneDefLoad parseSceneDef(std::string_view text, const std::string& file,
                           const std::string& baseDir) {
  // syntax first, then meaning; the offending value is found again in the text by its path
  SceneDef def;
  def.file = file;
  SceneReader reader(file, baseDir);
  return detail::parseSceneText(text, file, reader, std::move(def));
}

SceneDefLoad loadSceneDef(const std::string& path) {
  std::variant<detail::SceneFileText, SceneError> file = detail::readSceneFile(path);
  if (auto* e = std::get_if<SceneError>(&file)) return *e;
  const auto& [text, base] = std::get<detail::SceneFileText>(file);
  return parseSceneDef(text, path, base);
}

std::optional<std::pair<int, VesselSurface>> vesselSurfaceOf(
    const std::vector<SceneVessel>& vessels, int face) {
  const auto in = [face](const TriangleRange& r) { return face >= r.begin && face < r.end; };
  for (std::size_t v = 0; v < vessels.size(); ++v) {
    const SceneVessel& vessel = vessels[v];
    const int index = static_cast<int>(v);
    if (in(vessel.outerSurface)) return std::pair{index, VesselSurface::Outer};
    if (in(vessel.innerSurface)) return std::pair{index, VesselSurface::Inner};
    if (in(vessel.cutEnd)) return std::pair{index, VesselSurface::CutEnd};
    if (in(vessel.clampedEnd)) return std::pair{index, VesselSurface::ClampedEnd};
  }
  return std::nullopt;
}

}  // namespace microsim::sim
