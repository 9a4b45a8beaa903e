#pragma once
// What happened during an attempt, as data for assessment (DESIGN.md §Assessment) and for
// `microsim-cli run`: grabs, releases and grasps on nothing, pierces with their geometry, cuts, suture breaks,
// rejected input, tissue over-stretch and tears, and the knot read from the thread (throws formed, a knot
// tightened or slipped). The engine reports enums and numbers; words are the app's business.
//
// Units: millimetres, seconds, degrees; tensions in g·mm/s² (µN).

#include "microsim/sim/mesh/spring_model.h"
#include "microsim/sim/scene/input_frame.h"
#include "microsim/sim/suture/knot_tracker.h"

#include <cstdint>

namespace microsim::sim {

enum class SceneEventKind : std::uint8_t {
  /// a forceps closed on tissue: faces between its jaws are held (`index` = the lowest node
  /// it moves, `count` = how many nodes: the held faces' free corners)
  GrabTissue,
  ReleaseTissue,  ///< it opened: `count` nodes were freed
  /// a forceps closed on the suture (`index` = node, or the first node of the link it holds
  /// between two nodes; needle nodes ≤ swage)
  GripSuture,
  ReleaseSuture,  ///< it let go of the suture
  PierceEntry,    ///< the needle tip entered a wall (`index` into Scene::pierces())
  PierceExit,     ///< the needle tip left a wall (`index` into Scene::pierces())
  Cut,            ///< the scalpel removed `count` links
  SutureBreak,    ///< the suture broke at link `index`
  /// the suture slid out of a pierce (`index` into Scene::pierces(); −1 for a hole the scene
  /// started with, a stay stitch's)
  SuturePulledOut,
  /// the needle left a pierce before the thread reached it (drawn back, or moved off the
  /// hole by more than SutureDef::pierceReleaseDistance): the suture does not pass there
  /// (`index` into Scene::pierces())
  PierceReleased,
  InputRejected,  ///< a frame was unusable (`rejection`); the previous one was used instead
  /// a tissue link's stretch (l − r)/r rose above SceneDef::limits.overstretch: once when it
  /// starts (`index` = the link, `count` = its stretch in per-mille, rounded), then nothing
  /// for that link until it has fallen back to or below the threshold
  TissueOverStretch,
  /// links stretched above SceneDef::limits.tear were removed, like a cut (`index` = the
  /// first, `count` = how many this step)
  TissueTear,
  /// a forceps (`hand`) closed on nothing: no suture, and no tissue it may take, lay between
  /// its jaws
  GraspEmpty,
  /// microscissors (`hand`) cut the thread at link `index`; `value` = the cut-end length (mm,
  /// tools/microscissors.h), −1 when neither side of the cut is anchored in the tissue
  ThreadCut,
  /// after a cut (`hand`, `index` = the link), the needle keeps less free thread than
  /// NeedleDef::minTieLength: `value` = what it keeps (mm)
  ThreadTooShort,
  /// the knot in the thread gained a throw (suture/knot_tracker.h): `index` = which throw
  /// (0 = nearest the stitch), `count` = the knot's throws now, `value` = the thread's tension
  /// (µN); `knot` = the knot's type and the throw's handedness and wraps
  ThrowFormed,
  /// a knot of `count` throws was pulled tight: `value` = the tension (µN), `knot.type` its type
  KnotTightened,
  /// a tightened knot slipped: `count` = throws left, `value` = the tension (µN), `knot` = what
  /// is left of it, why it slipped and how far it ran along the thread
  KnotSlipped,
};

/// Which surface of a vessel a pierce crossed.
enum class VesselSurface : std::uint8_t { Outer, Inner, CutEnd, ClampedEnd, NotAVessel };
/// Which half of the circumference, seen from the microscope: the front wall faces the
/// camera, the back wall is the far side (catching it is the classic error).
enum class VesselWall : std::uint8_t { Front, Back };

struct PierceEvent {
  double time = 0.0;                ///< s, end of the step in which the tip crossed
  bool entry = true;                ///< into the wall (true) or out of it
  Vec3 point = Vec3::Zero();        ///< mm, where the hole is now
  Vec3 restPoint = Vec3::Zero();    ///< mm, where it is in the undeformed tissue: a dented or
                                    ///< dragged wall is judged where the tissue has the hole
  int face = -1;                    ///< tissue triangle
  Vec3 barycentric = Vec3::Zero();  ///< on the face's corners
  Vec3 tangent = Vec3::Zero();      ///< the needle's forward tangent where it passes `point`
                                    ///< (unit; at the tip for a wall punctured after a dent)
  Vec3 normal = Vec3::Zero();       ///< the face normal now, out of the wall material (unit)
  double angleDeg = 0.0;            ///< acos |τ·n₀|: τ the needle arc's tangent where its body
                                    ///< passed the wall (a dented wall: where the tip first
                                    ///< touched it, tools/needle.h), n₀ the undeformed face's
                                    ///< normal; 0 = perpendicular to the wall
  int vessel = -1;                  ///< index into SceneDef::vessels, -1 for other tissue
  int end = -1;                     ///< 0 or 1 for the ends of a severed vessel, else -1
  VesselSurface surface = VesselSurface::NotAVessel;
  VesselWall wall = VesselWall::Front;
  double biteMm = 0.0;              ///< restPoint's distance from the cut end along the axis (mm)
};

/// The knot of a ThrowFormed, KnotTightened or KnotSlipped event (suture::KnotEvent's fields
/// that SceneEvent's index, count and value do not carry).
struct SceneKnot {
  suture::KnotType type = suture::KnotType::None;               ///< the knot after the event
  suture::Handedness handedness = suture::Handedness::Right;    ///< ThrowFormed: the throw's
  int wraps = 0;                                                ///< ThrowFormed: the throw's
  double slide = 0.0;  ///< KnotSlipped: mm the knot ran along the thread
  suture::KnotSlipCause cause = suture::KnotSlipCause::StructureLost;  ///< KnotSlipped only
};

struct SceneEvent {
  SceneEventKind kind = SceneEventKind::GrabTissue;
  double time = 0.0;  ///< s
  int step = 0;       ///< the step it happened in (0-based)
  int hand = -1;      ///< 0 left, 1 right, -1 none
  int index = -1;     ///< see the kind
  int count = 0;      ///< see the kind
  double value = 0.0; ///< see the kind (a length or a force, in the units above)
  InputRejection rejection = InputRejection::NonFinite;  ///< InputRejected only
  SceneKnot knot;     ///< ThrowFormed, KnotTightened, KnotSlipped only
};

}  // namespace microsim::sim
