#include "microsim/sim/scene/spring_scene.h"

#include "microsim/sim/mesh/grid.h"
#include "microsim/sim/mesh/lattice.h"
#include "microsim/sim/mesh/merge.h"
#include "microsim/sim/mesh/tetra_lattice.h"
#include "microsim/sim/mesh/vessel.h"
#include "scene/scene_json_reader.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <exception>
#include <filesystem>
#include <set>
#include <utility>

namespace microsim::sim {

namespace {

using json = nlohmann::json;

// generator sizes beyond these would exhaust memory (or minutes of building) before they
// fail anywhere useful; the finest shipped scene has about 20,000 nodes
constexpr long long kMaxGeneratedNodes = 2'000'000;

// one object's part before merging: its mesh, the nodes it fixes and controls (local)
struct Part {
  SpringModel model;
  std::string name;
};

// the spring-scene objects, through the typed reads all scene loaders share
class Reader : public detail::JsonReader {
 public:
  explicit Reader(std::string baseDir) : baseDir_(std::move(baseDir)) {}

  bool scene(const json& doc, SpringScene& out);

 private:
  bool sizeLimit(long long nodes, const std::string& path) {
    return nodes <= kMaxGeneratedNodes || fail(SceneErrorKind::InvalidValue, path);
  }

  bool springMesh(const json& o, const std::string& path, SpringModel& m);
  bool lattice(const json& o, const std::string& path, SpringModel& m);
  bool vessel(const json& o, const std::string& path, SpringModel& m);
  bool grid(const json& o, const std::string& path, SpringModel& m);
  bool tetra(const json& o, const std::string& path, SpringModel& m);
  bool surface(const json& o, const std::string& path, SpringModel& m);
  bool fixedAndControls(const json& o, const std::string& path, SpringModel& part,
                        std::vector<std::pair<int, Vec3>>& controls);
  bool solver(const json& v, const std::string& path, SceneSolverSettings& out);

  std::string baseDir_;
};

bool Reader::springMesh(const json& o, const std::string& path, SpringModel& m) {
  if (!object(o, path, {"type", "name", "nodes", "links", "fixed", "controls", "mass", "damping"}))
    return false;
  double mass = 1.0;
  double damping = 0.0;
  if (const json* v = field(o, "mass"); v && !positive(*v, key(path, "mass"), mass)) return false;
  if (const json* v = field(o, "damping"); v && !nonNegative(*v, key(path, "damping"), damping))
    return false;

  // nodes: [[x, y, z], ...], at least one
  const json* nodes = nullptr;
  if (!required(o, path, "nodes", nodes)) return false;
  const std::string nodesPath = key(path, "nodes");
  if (!nodes->is_array()) return fail(SceneErrorKind::WrongType, nodesPath);
  if (nodes->empty()) return fail(SceneErrorKind::InvalidValue, nodesPath);
  for (std::size_t i = 0; i < nodes->size(); ++i) {
    Vec3 p;
    if (!vec3((*nodes)[i], index(nodesPath, i), p)) return false;
    m.addNode(p, mass, damping);
  }

  // links: [i, j, k] or [i, j, k, rest]
  const json* links = nullptr;
  if (!required(o, path, "links", links)) return false;
  const std::string linksPath = key(path, "links");
  if (!links->is_array()) return fail(SceneErrorKind::WrongType, linksPath);
  for (std::size_t li = 0; li < links->size(); ++li) {
    const json& l = (*links)[li];
    const std::string lp = index(linksPath, li);
    if (!l.is_array() || (l.size() != 3 && l.size() != 4))
      return fail(SceneErrorKind::WrongType, lp);
    int a = 0;
    int b = 0;
    double k = 0.0;
    double rest = -1.0;
    if (!nodeIndex(l[0], index(lp, 0), m.nodeCount(), a) ||
        !nodeIndex(l[1], index(lp, 1), m.nodeCount(), b))
      return false;
    if (a == b) return fail(SceneErrorKind::SelfLink, lp);
    if (!nonNegative(l[2], index(lp, 2), k)) return false;
    if (l.size() == 4 && !nonNegative(l[3], index(lp, 3), rest)) return false;
    m.addLink(a, b, k, rest);
  }
  return true;
}

bool Reader::lattice(const json& o, const std::string& path, SpringModel& m) {
  if (!object(o, path,
              {"type", "name", "size", "stiffness", "mass", "spacing", "fix_bottom", "fixed",
               "controls"}))
    return false;
  LatticeDef def;
  const json* size = nullptr;
  std::vector<int> n;
  if (!required(o, path, "size", size) || !ints(*size, key(path, "size"), 3, 2, n)) return false;
  if (n[1] != n[0] || n[2] != n[0]) return fail(SceneErrorKind::InvalidValue, key(path, "size"));
  if (!sizeLimit(1LL * n[0] * n[0] * n[0], key(path, "size"))) return false;
  def.n = n[0];
  if (const json* v = field(o, "stiffness"); v && !nonNegative(*v, key(path, "stiffness"), def.k))
    return false;
  if (const json* v = field(o, "mass"); v && !positive(*v, key(path, "mass"), def.mass))
    return false;
  if (const json* v = field(o, "spacing"); v && !positive(*v, key(path, "spacing"), def.spacing))
    return false;
  if (const json* v = field(o, "fix_bottom");
      v && !boolean(*v, key(path, "fix_bottom"), def.fixBottom))
    return false;
  m = latticeBox(def);
  return true;
}

bool Reader::vessel(const json& o, const std::string& path, SpringModel& m) {
  if (!object(o, path,
              {"type", "name", "preset", "radius", "wall_thickness", "length", "rings",
               "nodes_per_ring", "k_layer", "k_between", "mass", "damping", "clamp_first_ring",
               "origin", "direction", "fixed", "controls", "material"}))
    return false;
  VesselDef def;
  if (const json* v = field(o, "preset")) {
    if (!v->is_string()) return fail(SceneErrorKind::WrongType, key(path, "preset"));
    const std::string preset = v->get<std::string>();
    if (preset == "fine")
      def = VesselDef::fine();
    else if (preset != "paper")
      return fail(SceneErrorKind::InvalidValue, key(path, "preset"));
  }
  const std::pair<std::string_view, double*> positives[] = {{"radius", &def.radius},
                                                            {"wall_thickness", &def.wallThickness},
                                                            {"length", &def.length},
                                                            {"mass", &def.mass}};
  for (const auto& [name, target] : positives)
    if (const json* v = field(o, name); v && !positive(*v, key(path, name), *target)) return false;
  const std::pair<std::string_view, double*> nonNegatives[] = {
      {"k_layer", &def.kLayer}, {"k_between", &def.kBetween}, {"damping", &def.damping}};
  for (const auto& [name, target] : nonNegatives)
    if (const json* v = field(o, name); v && !nonNegative(*v, key(path, name), *target))
      return false;
  if (const json* v = field(o, "rings"); v && !intAtLeast(*v, key(path, "rings"), 2, def.rings))
    return false;
  if (const json* v = field(o, "nodes_per_ring");
      v && !intAtLeast(*v, key(path, "nodes_per_ring"), 3, def.nodesPerRing))
    return false;
  if (const json* v = field(o, "clamp_first_ring");
      v && !boolean(*v, key(path, "clamp_first_ring"), def.clampFirstRing))
    return false;
  if (const json* v = field(o, "origin"); v && !vec3(*v, key(path, "origin"), def.origin))
    return false;
  if (const json* v = field(o, "direction"); v && !vec3(*v, key(path, "direction"), def.direction))
    return false;
  if (!wallMaterial(o, path, def)) return false;
  if (def.wallThickness >= def.radius)
    return fail(SceneErrorKind::InvalidValue, key(path, "wall_thickness"));
  if (!(def.direction.norm() > 0.0))
    return fail(SceneErrorKind::InvalidValue, key(path, "direction"));
  if (!sizeLimit(2LL * def.rings * def.nodesPerRing, path)) return false;
  m = sim::vessel(def).model;
  return true;
}

bool Reader::grid(const json& o, const std::string& path, SpringModel& m) {
  if (!object(o, path,
              {"type", "name", "cells", "size", "stiffness", "mass", "fix_border", "fixed",
               "controls"}))
    return false;
  GridDef def;
  if (const json* v = field(o, "cells")) {
    std::vector<int> cells;
    if (!ints(*v, key(path, "cells"), 2, 1, cells)) return false;
    if (!sizeLimit((cells[0] + 1LL) * (cells[1] + 1LL), key(path, "cells"))) return false;
    def.cellsX = cells[0];
    def.cellsY = cells[1];
  }
  if (const json* v = field(o, "size"); v && !positive(*v, key(path, "size"), def.size))
    return false;
  if (const json* v = field(o, "stiffness"); v && !nonNegative(*v, key(path, "stiffness"), def.k))
    return false;
  if (const json* v = field(o, "mass"); v && !positive(*v, key(path, "mass"), def.mass))
    return false;
  if (const json* v = field(o, "fix_border");
      v && !boolean(*v, key(path, "fix_border"), def.fixBorder))
    return false;
  m = gridMesh(def);
  return true;
}

bool Reader::tetra(const json& o, const std::string& path, SpringModel& m) {
  if (!object(o, path,
              {"type", "name", "size", "spacing", "stiffness", "mass", "fix_bottom", "fixed",
               "controls"}))
    return false;
  TetraLatticeDef def;
  if (const json* v = field(o, "size")) {
    std::vector<int> n;
    if (!ints(*v, key(path, "size"), 3, 2, n)) return false;
    if (!sizeLimit(1LL * n[0] * n[1] * n[2], key(path, "size"))) return false;
    def.nx = n[0];
    def.ny = n[1];
    def.nz = n[2];
  }
  if (const json* v = field(o, "spacing"); v && !positive(*v, key(path, "spacing"), def.spacing))
    return false;
  if (const json* v = field(o, "stiffness"); v && !nonNegative(*v, key(path, "stiffness"), def.k))
    return false;
  if (const json* v = field(o, "mass"); v && !positive(*v, key(path, "mass"), def.mass))
    return false;
  if (const json* v = field(o, "fix_bottom");
      v && !boolean(*v, key(path, "fix_bottom"), def.fixBottom))
    return false;
  m = tetraLattice(def).model;
  return true;
}

bool Reader::surface(const json& o, const std::string& path, SpringModel& m) {
  if (!object(o, path,
              {"type", "name", "file", "weld", "weld_tolerance", "scale", "stiffness", "mass",
               "fixed", "controls"}))
    return false;
  SurfaceMeshOptions opt;
  const json* file = nullptr;
  if (!required(o, path, "file", file)) return false;
  if (!file->is_string()) return fail(SceneErrorKind::WrongType, key(path, "file"));
  if (const json* v = field(o, "weld"); v && !boolean(*v, key(path, "weld"), opt.weld))
    return false;
  if (const json* v = field(o, "weld_tolerance");
      v && !positive(*v, key(path, "weld_tolerance"), opt.weldTolerance))
    return false;
  if (const json* v = field(o, "scale"); v && !positive(*v, key(path, "scale"), opt.scale))
    return false;
  if (const json* v = field(o, "stiffness"); v && !nonNegative(*v, key(path, "stiffness"), opt.k))
    return false;
  if (const json* v = field(o, "mass"); v && !positive(*v, key(path, "mass"), opt.mass))
    return false;

  // relative to the scene file's directory
  std::filesystem::path p = file->get<std::string>();
  if (p.is_relative()) p = std::filesystem::path(baseDir_) / p;
  SurfaceImport imported = importSurfaceMesh(p.string(), opt);
  if (auto* e = std::get_if<MeshImportError>(&imported)) {
    fail(SceneErrorKind::MeshImport, key(path, "file"));
    error()->meshError = *e;
    return false;
  }
  m = std::move(std::get<SpringModel>(imported));
  return true;
}

bool Reader::fixedAndControls(const json& o, const std::string& path, SpringModel& part,
                              std::vector<std::pair<int, Vec3>>& controls) {
  const int n = part.nodeCount();
  if (const json* fixed = field(o, "fixed")) {
    const std::string fp = key(path, "fixed");
    if (!fixed->is_array()) return fail(SceneErrorKind::WrongType, fp);
    for (std::size_t i = 0; i < fixed->size(); ++i) {
      int node = 0;
      if (!nodeIndex((*fixed)[i], index(fp, i), n, node)) return false;
      part.setFixed(node);
    }
  }
  if (const json* list = field(o, "controls")) {
    const std::string cp = key(path, "controls");
    if (!list->is_array()) return fail(SceneErrorKind::WrongType, cp);
    std::set<int> seen;
    for (std::size_t i = 0; i < list->size(); ++i) {
      const json& c = (*list)[i];
      const std::string p = index(cp, i);
      if (!object(c, p, {"node", "displacement"})) return false;
      const json* node = nullptr;
      const json* displacement = nullptr;
      if (!required(c, p, "node", node) || !required(c, p, "displacement", displacement))
        return false;
      int local = 0;
      Vec3 d;
      if (!nodeIndex(*node, key(p, "node"), n, local) ||
          !vec3(*displacement, key(p, "displacement"), d))
        return false;
      if (!seen.insert(local).second) return fail(SceneErrorKind::DuplicateControl, key(p, "node"));
      if (part.isFixed(local)) return fail(SceneErrorKind::InvalidValue, key(p, "node"));
      controls.emplace_back(local, d);
    }
  }
  return true;
}

bool Reader::solver(const json& v, const std::string& path, SceneSolverSettings& out) {
  if (!object(v, path, {"name", "alpha", "cutout", "momentum", "iterations", "budget_ms"}))
    return false;
  double x = 0.0;
  if (const json* f = field(v, "name")) {
    if (!f->is_string()) return fail(SceneErrorKind::WrongType, key(path, "name"));
    out.name = f->get<std::string>();
  }
  if (const json* f = field(v, "alpha")) {
    if (!nonNegative(*f, key(path, "alpha"), x)) return false;
    out.alpha = x;
  }
  if (const json* f = field(v, "cutout")) {
    if (!nonNegative(*f, key(path, "cutout"), x)) return false;
    out.cutout = x;
  }
  if (const json* f = field(v, "momentum")) {
    if (!nonNegative(*f, key(path, "momentum"), x)) return false;
    if (x >= 1.0) return fail(SceneErrorKind::InvalidValue, key(path, "momentum"));
    out.momentum = x;
  }
  if (const json* f = field(v, "iterations")) {
    int k = 0;
    if (!intAtLeast(*f, key(path, "iterations"), 1, k)) return false;
    out.iterations = k;
  }
  if (const json* f = field(v, "budget_ms")) {
    if (!positive(*f, key(path, "budget_ms"), x)) return false;
    out.budgetMs = x;
  }
  return true;
}

bool Reader::scene(const json& doc, SpringScene& out) {
  if (!object(doc, "", {"objects", "gravity", "solver"})) return false;
  const json* objects = nullptr;
  if (!required(doc, "", "objects", objects)) return false;
  if (!objects->is_array()) return fail(SceneErrorKind::WrongType, "objects");
  if (objects->empty()) return fail(SceneErrorKind::InvalidValue, "objects");
  if (const json* g = field(doc, "gravity"); g && !vec3(*g, "gravity", out.model.gravity))
    return false;
  if (const json* s = field(doc, "solver"); s && !solver(*s, "solver", out.solver)) return false;

  for (std::size_t i = 0; i < objects->size(); ++i) {
    const json& o = (*objects)[i];
    const std::string path = index("objects", i);
    if (!o.is_object()) return fail(SceneErrorKind::WrongType, path);
    const json* type = nullptr;
    if (!required(o, path, "type", type)) return false;
    if (!type->is_string()) return fail(SceneErrorKind::WrongType, key(path, "type"));
    SceneObject info;
    info.type = type->get<std::string>();
    if (const json* name = field(o, "name")) {
      if (!name->is_string()) return fail(SceneErrorKind::WrongType, key(path, "name"));
      info.name = name->get<std::string>();
    }

    // the object's own mesh, then its fixed nodes and controls
    SpringModel part;
    bool ok = false;
    if (info.type == "spring-mesh")
      ok = springMesh(o, path, part);
    else if (info.type == "lattice")
      ok = lattice(o, path, part);
    else if (info.type == "vessel")
      ok = vessel(o, path, part);
    else if (info.type == "grid")
      ok = grid(o, path, part);
    else if (info.type == "tetra-lattice")
      ok = tetra(o, path, part);
    else if (info.type == "surface-mesh")
      ok = surface(o, path, part);
    else
      return fail(SceneErrorKind::UnknownObjectType, key(path, "type"));
    std::vector<std::pair<int, Vec3>> controls;
    if (!ok || !fixedAndControls(o, path, part, controls)) return false;

    // merged in declaration order
    info.firstNode = out.model.nodeCount();
    info.firstLink = out.model.linkCount();
    info.firstTriangle = static_cast<int>(out.model.triangles().size());
    if (!sizeLimit(1LL * info.firstNode + part.nodeCount(), path)) return false;
    const int offset = appendModel(out.model, part);
    info.nodeCount = part.nodeCount();
    info.linkCount = part.linkCount();
    info.triangleCount = static_cast<int>(part.triangles().size());
    for (const auto& [local, d] : controls)
      out.controls.add(offset + local, out.model.restPositions().col(offset + local) + d);
    out.objects.push_back(std::move(info));
  }
  out.model.finalize();
  return true;
}

}  // namespace

std::pair<int, int> lineColumnAt(std::string_view text, std::size_t offset) {
  offset = std::min(offset, text.size());
  int line = 1;
  std::size_t lineStart = 0;
  for (std::size_t i = 0; i < offset; ++i)
    if (text[i] == '\n') {
      ++line;
      lineStart = i + 1;
    }
  return {line, static_cast<int>(offset - lineStart) + 1};
}

SceneLoad parseSpringScene(std::string_view text, const std::string& file,
                           const std::string& baseDir) {
  // syntax first, then meaning; the offending value is found again in the text by its path
  Reader reader(baseDir);
  return detail::parseSceneText(text, file, reader, SpringScene{});
}

SceneLoad loadSpringScene(const std::string& path) {
  std::variant<detail::SceneFileText, SceneError> file = detail::readSceneFile(path);
  if (auto* e = std::get_if<SceneError>(&file)) return *e;
  const auto& [text, base] = std::get<detail::SceneFileText>(file);
  return parseSpringScene(text, path, base);
}

}  // namespace microsim::sim
