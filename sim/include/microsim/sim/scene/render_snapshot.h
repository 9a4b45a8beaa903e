#pragma once
// What the viewport draws of one simulated step (DESIGN.md §Data flow of one frame): the
// tissue's positions and per-vertex normals, the suture's nodes, what each hand holds, each
// tool's pose, and what each forceps' jaws would close on now (the contact cue;
// Scene::betweenJaws).
//
// The simulation thread fills a snapshot after each step and hands it over (double buffer or
// short lock); the GUI thread only reads it. Everything is a plain value: floats laid out
// for a vertex buffer (x y z per vertex), no pointer into the scene, so a snapshot outlives
// the step that made it. Static geometry (the tissue's triangles, a jaw's mesh) is the
// scene's and is read once from Scene::def() / Scene::tissue(); a snapshot carries only what
// moves. `fill` reuses the snapshot's buffers, so a steady stream of steps allocates nothing.
//
// Units: millimetres, seconds.

#include "microsim/sim/scene/input_frame.h"

#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <vector>

namespace microsim::sim {

class Scene;

/// What a forceps' jaws would take if they closed now (Scene::betweenJaws), as the viewport
/// shows it. Stored nowhere: append freely.
enum class JawTarget : std::uint8_t {
  Nothing,
  Tissue,  ///< a tissue face lies between the jaws
  Needle,  ///< the needle's body (a needle link)
  Thread,  ///< the thread (a link past the swage)
};

struct ToolSnapshot {
  bool present = false;                                ///< the scene declares this tool
  Eigen::Matrix4f pose = Eigen::Matrix4f::Identity();  ///< tool frame → scene
  double closure = 0.0;                                ///< 0 open .. 1 closed (forceps)
  /// Each jaw's transform, jaw mesh frame → scene: [0] upper, [1] lower (forceps only; the
  /// lower jaw's mesh is mirrored in y, see tools::jawPoses).
  std::array<Eigen::Matrix4f, 2> jaws{Eigen::Matrix4f::Identity(), Eigen::Matrix4f::Identity()};
  bool holdsTissue = false;
  bool holdsSuture = false;
  /// What the jaws would close on from their closure now: the suture point nearest where
  /// they meet, else the tissue faces between them (forceps only).
  JawTarget between = JawTarget::Nothing;
  /// Where (scene, mm): that suture point, or the area-weighted centroid of the faces' parts
  /// between the jaws; the tool tip when `between` is Nothing.
  Eigen::Vector3f betweenPoint = Eigen::Vector3f::Zero();
};

/// A scalpel in a hand: present while the hand holds it (InputFrame's instrument), and then
/// its blade frame → scene (tools/scalpel.h: the blade is [0, length] × {0} × [0, height]).
struct ScalpelSnapshot {
  bool present = false;
  Eigen::Matrix4f pose = Eigen::Matrix4f::Identity();
};

/// Microscissors in a hand: present while the hand holds them (InputFrame's instrument) and
/// the scene declares them; the tool frame → scene, how closed, and each blade's transform
/// (blade frame → scene, tools::scissorsBladePoses: [0] upper, [1] lower, mirrored in y).
struct ScissorsSnapshot {
  bool present = false;
  Eigen::Matrix4f pose = Eigen::Matrix4f::Identity();
  double closure = 0.0;  ///< 0 open .. 1 closed
  std::array<Eigen::Matrix4f, 2> blades{Eigen::Matrix4f::Identity(), Eigen::Matrix4f::Identity()};
};

struct RenderSnapshot {
  double time = 0.0;  ///< s, scene time at the end of the step
  int steps = 0;
  /// Tissue vertices, 3 floats each (mm), in the order of Scene::tissue() nodes.
  std::vector<float> tissuePositions;
  /// Unit per-vertex normals, 3 floats each: the area-weighted mean of the normals of the
  /// triangles around the vertex; (0, 0, 0) for a node on no triangle.
  std::vector<float> tissueNormals;
  /// Suture nodes, 3 floats each (mm); empty without a needle. The first `needleNodes` are
  /// the rigid needle, the rest the thread.
  std::vector<float> suturePositions;
  /// Per suture link: 1 intact, 0 broken (a broken link is not drawn).
  std::vector<std::uint8_t> sutureAlive;
  int needleNodes = 0;
  float sutureRadius = 0.0f;  ///< mm, the thread's contact radius
  std::array<ToolSnapshot, 2> forceps;  ///< by hand: [0] left, [1] right
  std::array<ScalpelSnapshot, 2> scalpels;  ///< by hand: [0] left, [1] right
  std::array<ScissorsSnapshot, 2> scissors;  ///< by hand: [0] left, [1] right
  /// What each hand held in the last frame stepped (Scene::instrument), by hand.
  std::array<Instrument, kHandCount> instruments{Instrument::Forceps, Instrument::Forceps};
  int pierceCount = 0;                  ///< pierce events so far
};

/// Fills `out` from the scene's current state, reusing its buffers.
void fillSnapshot(const Scene& scene, RenderSnapshot& out);

/// Per-vertex normals of a triangle mesh (area-weighted), 3 floats per vertex, written into
/// `normals` (resized to positions.size()). Shared by the snapshot and by static meshes.
void vertexNormals(const std::vector<float>& positions,
                   const std::vector<std::array<int, 3>>& triangles, std::vector<float>& normals);

}  // namespace microsim::sim
