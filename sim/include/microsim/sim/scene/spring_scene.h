#pragma once
// Spring scene files: the JSON a user writes to describe a tissue network for
// `microsim-cli solve` and `export` (DESIGN.md §Headless interface).
//
//   {"objects": [ OBJECT, ... ],           required, at least one
//    "gravity": [x, y, z],                 optional, mm/s²; off unless given
//    "solver": {"name", "alpha", "cutout", "momentum", "iterations", "budget_ms"}}  optional
//
// OBJECT is one of (every key but "type" optional unless marked required):
//   {"type": "spring-mesh", "name", "nodes": [[x,y,z], ...] (required, mm),
//    "links": [[i, j, k] | [i, j, k, rest], ...] (required; k g/s², rest mm, default the
//    initial length), "mass" (g, 1), "damping" (g/s, 0)}
//   {"type": "lattice", "size": [n, n, n] (required, n ≥ 2), "stiffness" (10), "mass",
//    "spacing" (mm, 1), "fix_bottom" (true)}
//   {"type": "vessel", "preset": "paper" | "fine", "radius", "wall_thickness",
//    "length" (mm), "rings", "nodes_per_ring", "k_layer", "k_between", "mass",
//    "damping", "clamp_first_ring", "origin" [x,y,z], "direction" [x,y,z], "material":
//    {"youngs_modulus" (g/(mm·s²) = Pa, 3e5), "fung_exponent" (6), "density" (g/mm³,
//    1.06e-3), "damping_ratio" (1)}}  (VesselDef, WallMaterial: with a material the links
//    follow the exponential law with k0 = E·A/L and masses come from the density; an
//    explicit "k_layer", "k_between", "mass" or "damping" still wins)
//   {"type": "grid", "cells": [cx, cy] (100 by 100), "size" (cell edge, mm, 1),
//    "stiffness", "mass", "fix_border" (false)}
//   {"type": "tetra-lattice", "size": [nx, ny, nz] (146, 70, 4), "spacing", "stiffness",
//    "mass", "fix_bottom" (true)}
//   {"type": "surface-mesh", "file" (required; relative to the scene file), "weld"
//    (true), "weld_tolerance" (mm), "scale" (mm per file unit), "stiffness", "mass"}
// and every object may carry "name", "fixed": [node, ...] (added to the generator's own)
// and "controls": [{"node": i, "displacement": [x,y,z] (mm, from the rest position)}].
// Node indices inside an object are local to it; objects merge into one SpringModel in
// declaration order, each one's indices shifted by the nodes before it.
//
// Loading never throws and never prints: it returns the scene or a SceneError naming the
// kind of problem, the file, the position in it and the field path, e.g.
// "objects[0].links[3]". Unknown keys are errors too (a typo must not silently fall back
// to a default).

#include "microsim/sim/mesh/spring_model.h"
#include "microsim/sim/mesh/surface_import.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace microsim::sim {

/// Solver settings a scene may carry; the CLI's flags override them.
struct SceneSolverSettings {
  std::optional<std::string> name;
  std::optional<double> alpha;     ///< qss step scale (mm per force unit)
  std::optional<double> cutout;    ///< qss per-level cutout ε (mm)
  std::optional<double> momentum;  ///< qss momentum β in [0, 1)
  std::optional<int> iterations;   ///< iteration limit
  std::optional<double> budgetMs;  ///< wall-clock limit (ms)
};

/// Where one declared object landed in the merged model.
struct SceneObject {
  std::string type;  ///< "spring-mesh", "lattice", ...
  std::string name;  ///< as declared, or empty
  int firstNode = 0;
  int nodeCount = 0;
  int firstLink = 0;
  int linkCount = 0;
  int firstTriangle = 0;
  int triangleCount = 0;
};

struct SpringScene {
  SpringModel model;        ///< every object merged, finalized
  SpringControls controls;  ///< targets = rest position + displacement, global indices
  std::vector<SceneObject> objects;
  SceneSolverSettings solver;
};

enum class SceneErrorKind : std::uint8_t {
  FileNotFound,       ///< the scene file cannot be opened
  MalformedJson,      ///< not JSON; line/column point at the parse failure
  WrongType,          ///< a field has the wrong JSON type or array length
  MissingField,       ///< a required field is absent
  UnknownField,       ///< a key this object type does not have
  UnknownObjectType,  ///< "type" names no known object
  IndexOutOfRange,    ///< a node index outside the object
  SelfLink,           ///< a link from a node to itself
  NegativeValue,      ///< a stiffness, rest length, mass, ... below zero
  NonFinite,          ///< NaN or infinite (e.g. 1e999)
  DuplicateControl,   ///< the same node controlled twice
  InvalidValue,       ///< out of its range otherwise (size < 2, control on a fixed node, ...)
  MeshImport,         ///< a surface-mesh file failed (see meshError)
};

struct SceneError {
  SceneErrorKind kind = SceneErrorKind::MalformedJson;
  std::string file;        ///< the scene file as given (or the label passed to parse)
  int line = 0;            ///< 1-based; 0 when unknown
  int column = 0;          ///< 1-based, in bytes
  std::size_t offset = 0;  ///< byte offset of the offending value
  std::string field;       ///< JSON path, e.g. "objects[0].links[3]"; empty for the root
  std::optional<MeshImportError> meshError;  ///< for MeshImport: the importer's error
};

using SceneLoad = std::variant<SpringScene, SceneError>;

/// Reads and parses the scene file at `path`; surface-mesh files resolve against its
/// directory.
SceneLoad loadSpringScene(const std::string& path);
/// Parses scene JSON from memory. `file` labels errors; `baseDir` resolves surface-mesh
/// paths.
SceneLoad parseSpringScene(std::string_view text, const std::string& file = {},
                           const std::string& baseDir = ".");

/// The 1-based line and column of byte `offset` in `text`.
std::pair<int, int> lineColumnAt(std::string_view text, std::size_t offset);

}  // namespace microsim::sim
