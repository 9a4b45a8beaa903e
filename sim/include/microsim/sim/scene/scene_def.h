#pragma once
// The microsurgery scene file: everything one simulated attempt needs, declared, so that
// only what is declared is built and simulated (DESIGN.md "model only what a scene needs").
// The schema is resources/schema/scene.schema.json; examples are in resources/scenes/.
//
//   {"version": 1,                                   optional; 1 is the only version
//    "objects": [ OBJECT, ... ],                     required, at least one (the tissue)
//    "gravity": [x, y, z],                           mm/s², off unless given
//    "solver": {"name" ("newton"), "iterations" (20), "tolerance" (1e-6), "alpha",
//               "relaxation", "cutout", "momentum", "damping", "active_region",
//               "linear_tolerance"},
//    "tools": {"forceps": [FORCEPS, ...] (at most one per hand),
//              "needle": NEEDLE, "scalpel": SCALPEL, "scissors": SCISSORS}, each optional
//    "camera": {"eye", "target", "up" ([x,y,z] mm), "fov_deg"},
//    "step": {"rate_hz" (100), "budget_ms" (8)},
//    "surface": {"subdivision" (0..4, 0)}: the drawn tissue refined that many times into a
//              smooth surface through its nodes (mesh/smooth_surface.h); drawing only, the
//              simulation is the same
//    "tissue": {"overstretch", "tear"},       stretch limits (l − r)/r, each off unless given:
//              above "overstretch" a link raises SceneEventKind::TissueOverStretch once
//              (again only after it fell back), above "tear" it is removed (TissueTear)
//    "collision": {"tree": "aabb" (default) | "sphere",
//                  "tissue" (true): tissue against tissue, "tools" (true): jaws against
//                  tissue (both need a solver that takes soft terms: newton, reference),
//                  "stiffness" (g/s², 20 × the stiffest link), "thickness" (mm, 0.01),
//                  "reach" (mm, 0.1), "self_distance" (mm, 0.3): collide/tissue_contact.h}}
//
// OBJECT is any object of a spring scene (spring_scene.h: spring-mesh, lattice, vessel,
// grid, tetra-lattice, surface-mesh; read by that loader, so its rules and errors hold) or
//   {"type": "severed-vessel", "name", "gap" (mm between the cut ends, 0.5), "center"
//    ([x,y,z] mm, midpoint of the gap), "axis" ([x,y,z], from end 0 to end 1), and the
//    vessel fields "preset", "radius", "wall_thickness", "length", "rings",
//    "nodes_per_ring", "k_layer", "k_between", "mass", "damping", "clamp_first_ring",
//    "material" (as for "vessel" in spring_scene.h)}:
//    two vessel ends, each clamped at its far ring, their cut ends facing across the gap.
// FORCEPS: {"hand": "left"|"right" (required), "mesh" (required, OBJ/glTF of one jaw,
//    relative to the scene file), "scale" (mm per file unit, 1), "opening_deg" (20),
//    "hold_stiffness" (g/s², 3e5), "close_at" (closure, 0.8)}
// NEEDLE: {"shape": "curved"|"straight", "radius", "length" (needle, mm), "thread_length"
//    (mm), "links", "needle_links", "break_stretch", "contact_radius", "friction", "drag",
//    "position" ([x,y,z] mm) and "rotation" ([w,x,y,z], needle frame → scene) of the needle
//    at the start, "solver" ("direct"|"ftl"), "substeps", "iterations", "coupling_gain",
//    "coupling_stiffness" (g/s², suture_coupling.h), "puncture_force" (µN, 0),
//    "min_tie_length" (mm, 3)}
// SCISSORS: {"blade_length" (mm, 0.6), "opening_deg" (25), "blade_half_thickness" (mm, 0.03),
//    "cut_at" (closure, 0.9)}: microscissors for any hand whose instrument is Scissors
// SCALPEL: {"blade_length" (mm, 2), "blade_height" (mm, 0.5)}
//
// Loading never throws and never prints; errors are SceneError (spring_scene.h) with the
// file, line, column and field path ("tools.forceps[1].mesh"); a missing tool mesh is
// SceneErrorKind::MeshImport with the importer's error.

#include "microsim/sim/collide/tissue_contact.h"
#include "microsim/sim/mesh/spring_model.h"
#include "microsim/sim/mesh/vessel.h"
#include "microsim/sim/scene/input_frame.h"
#include "microsim/sim/scene/scene_events.h"
#include "microsim/sim/scene/spring_scene.h"
#include "microsim/sim/scene/stay_stitch.h"
#include "microsim/sim/solve/solver.h"
#include "microsim/sim/suture/knot_tracker.h"
#include "microsim/sim/suture/suture_coupling.h"
#include "microsim/sim/suture/suture_model.h"
#include "microsim/sim/suture/suture_solver.h"

#include <Eigen/Geometry>

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace microsim::sim {

inline constexpr int kSceneFileVersion = 1;

/// A vessel of the scene and where its parts sit in the merged tissue model.
struct SceneVessel {
  int object = 0;       ///< index into SceneDef::tissue.objects
  int end = -1;         ///< 0 or 1 for the ends of a severed vessel, -1 for a single vessel
  VesselDef def;        ///< the generator's parameters (origin, direction as placed)
  int firstNode = 0;    ///< node offset in the merged model
  int firstTriangle = 0;
  TriangleRange outerSurface;  ///< global triangle indices
  TriangleRange innerSurface;
  TriangleRange clampedEnd;
  TriangleRange cutEnd;
};

/// The vessel (index into `vessels`) and the surface of it that tissue face `face` lies on;
/// none for a face of another object.
std::optional<std::pair<int, VesselSurface>> vesselSurfaceOf(
    const std::vector<SceneVessel>& vessels, int face);

/// Microscope defaults for the viewport (mm, degrees).
struct CameraDef {
  Vec3 eye = Vec3(0.0, -8.0, 40.0);  ///< mm
  Vec3 target = Vec3::Zero();        ///< mm
  Vec3 up = Vec3::UnitY();
  double fovDeg = 12.0;  ///< vertical field of view (degrees)
};

/// One forceps: two rigid jaws of the same triangulated shape (tools/forceps.h).
struct ForcepsDef {
  Hand hand = Hand::Left;
  std::string meshFile;           ///< as resolved at load
  Points jawVertices{3, 0};       ///< the jaw in its frame, mm (tip at the origin, along +x)
  std::vector<std::array<int, 3>> jawTriangles;
  double openingDeg = 20.0;       ///< angle of each jaw off the axis when open (degrees)
  /// g/s²: how stiffly a grasp holds the tissue (tools/forceps.h: the hold), shared among
  /// the points it holds
  double holdStiffness = 3e5;
  double closeAt = 0.8;           ///< closure (0..1) at and above which the jaws hold
  /// s: the least time the jaws take from closed to fully open. Their spring opens them at a
  /// finite speed, whatever the hand or a button does, so an opening jaw meets the wall it
  /// swings into and pushes it aside (tools/jaw_contact.h) instead of landing inside it
  double openingSeconds = 0.1;
};

/// The needle with its suture (suture/suture_model.h) and how it steps.
struct NeedleDef {
  suture::SutureDef suture;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  ///< needle frame → scene at start
  std::string solver = "direct";
  suture::SutureStepParams step;    ///< dt is overwritten with the scene's step
  suture::CouplingParams coupling;
  /// µN: the force at which the tip punctures a wall it presses on; until then the wall dents
  /// (tools/needle_indent.h). 0 = a crossing pierces at once (also with solvers that take no
  /// soft terms).
  double punctureForce = 0.0;
  /// mm: the least free thread the needle must keep to tie the next instrument knot (two
  /// turns around a 0.2 mm jaw, ≈ 1.3 mm, and the reach from the stitch to the jaw); a cut
  /// that leaves less is reported (SceneEventKind::ThreadTooShort)
  double minTieLength = 3.0;
  /// mm, scene frame: the chain's nodes at the start, 3 by (links + 1), for a thread that is
  /// already laid (a knot tied, a stitch placed); empty (or another size): laid out straight
  /// at `pose`
  suture::Points initialShape{3, 0};
  /// holes the thread already passes when the scene starts, in the order a needle makes them
  /// (path order, suture_constraints.h), each at its node of `initialShape`; they carry no
  /// PierceEvent
  std::vector<suture::Pierce> initialPierces;
  /// a stitch already placed (stay_stitch.h): the loader lays the thread (`initialShape`,
  /// `initialPierces`) from it
  std::optional<StayStitchDef> stayStitch;
  /// how the thread is read for a knot each step (events: throws formed, tightened, slipped)
  suture::KnotTrackerDef knots;
};

/// Microscissors (tools/microscissors.h): two straight blades hinged at `bladeLength` from
/// the tip, cutting the thread where they close.
struct ScissorsDef {
  double bladeLength = 0.6;         ///< mm, tip to pivot
  double openingDeg = 25.0;         ///< each blade's angle off the axis when open (degrees)
  double bladeHalfThickness = 0.03; ///< mm, half the blades' thickness out of their plane
  double cutAt = 0.9;               ///< closure (0..1) whose crossing upwards cuts
};

/// A scalpel blade: the rectangle [0, length] × {0} × [0, height] of the tool frame; the
/// cutting edge is its x axis from the tip (tools/scalpel.h).
struct ScalpelDef {
  double bladeLength = 2.0;  ///< mm
  double bladeHeight = 0.5;  ///< mm
};

struct TissueSolverDef {
  std::string name = "newton";
  SolverParams params;
  int iterations = 20;        ///< per step
  double tolerance = 1e-6;    ///< relative residual that ends a step's solve early
};

/// How the tissue is drawn (the viewport's business; the engine steps the same either way).
struct SurfaceDef {
  int subdivision =
      0;  ///< Loop subdivision levels of the drawn surface, 0 = the simulated triangles
};

struct StepDef {
  double rateHz = 100.0;    ///< fixed step rate (Hz): dt = 1 / rate
  double budgetMs = 8.0;    ///< wall-clock budget of one step (ms), used by real-time stepping
};

/// Stretch limits of the tissue's links, for assessment; stretch = (l − r)/r, l the length
/// and r the rest length (dimensionless). Checked after every step's tissue solve on the
/// links of the nodes that moved; 0 turns a limit off.
struct TissueLimitsDef {
  double overstretch = 0.0;  ///< above it a link is over-stretched (an event), 0 = off
  double tear = 0.0;         ///< above it a link tears (is removed, an event), 0 = off
};

enum class CollisionTree : std::uint8_t { Aabb, Sphere };

/// Contact of the tissue with itself and with the forceps' jaws (collide/tissue_contact.h,
/// tools/jaw_contact.h). Needs a tissue solver that takes soft terms; off otherwise.
struct ContactDef {
  bool tissue = true;  ///< tissue against tissue
  bool tools = true;   ///< the forceps' jaws against the tissue
  collide::TissueContactParams params;
};

struct SceneDef {
  std::string file;  ///< the scene file as given, empty when parsed from memory
  SpringScene tissue;                  ///< merged tissue model, static controls, objects
  std::vector<SceneVessel> vessels;    ///< the vessels among the objects, in order
  std::array<std::optional<ForcepsDef>, kHandCount> forceps;  ///< by hand
  std::optional<NeedleDef> needle;
  std::optional<ScalpelDef> scalpel;
  std::optional<ScissorsDef> scissors;
  TissueSolverDef solver;
  CameraDef camera;
  StepDef step;
  SurfaceDef surface;
  TissueLimitsDef limits;
  CollisionTree tree = CollisionTree::Aabb;
  ContactDef contact;
};

using SceneDefLoad = std::variant<SceneDef, SceneError>;

/// Reads the scene file at `path`; mesh files resolve against its directory.
SceneDefLoad loadSceneDef(const std::string& path);
/// Parses scene JSON from memory; `file` labels errors, `baseDir` resolves mesh files.
SceneDefLoad parseSceneDef(std::string_view text, const std::string& file = {},
                           const std::string& baseDir = ".");

}  // namespace microsim::sim
