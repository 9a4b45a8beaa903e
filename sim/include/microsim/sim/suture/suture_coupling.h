#pragma once
// Coupling of the suture and the tissue at pierce points (Brown et al. 2002 §4, Fig. 7),
// without touching the tissue solvers.
//
// Each frame, in this order:
//   1. readPiercePoints: every pierce point is re-read from the tissue, P = u a + v b + w c
//      for its face (a, b, c) and barycentrics (u, v, w), so the suture follows the vessel;
//   2. the suture steps (suture_solver.h): it slides through the pierces to relieve stretch;
//   3. couplingControls: what stretch sliding could not relieve pulls the tissue, where the
//      thread is anchored on both sides. A pierce with only pierces between it and a free end
//      pulls nothing: that end feeds thread through them as fast as it is drawn (a thread
//      drawn through the walls without a knot leaves them where they are; sliding moves whole
//      links, so without this rule the sub-link excess it leaves would tow the wall a little
//      every frame). A pierce P with a grip somewhere on each side, between neighbouring
//      constraints Q (grip or pierce), slides freely, so one tension runs through it: with e =
//      max_sides (|Q − P| − arc) the tightest side's excess length, every taut side pulls P towards
//      its Q by e:
//          pull(P) = max(e, 0) · Σ_{taut sides} (Q − P)/|Q − P|              (mm)
//      where a side is taut when |Q − P| ≥ arc − l (within one link of straight: sliding moves
//      whole links, so a side can stay up to one link short of taut). Each free (not fixed)
//      corner node of the pierced face becomes a control node with target
//      x_node + gain · pull(P) (pulls of several pierces on one node are averaged), which the
//      existing tissue solvers honour as SpringControls (a forceps grab does the same).
//      A pierce with a taut side but no excess left (the tissue took it last frame) holds its
//      face where it is (pull 0): a taut thread carries the tissue's tension. Releasing it
//      instead let the tissue spring back, be pulled again the next frame, and so on, every
//      other frame a whole-vessel solve from scratch. The hold is a position control, so it
//      also stops the face moving towards Q (which a thread cannot resist) until the side
//      goes slack by more than a link, e.g. when the hand comes back.
//   4. the tissue solves with those controls; the next frame reads the moved points back.
// A knot over the stitch (KnotOverStitch). Through a knot no side runs straight to a grip, so
// by the rule above a knot pulled tight carries nothing to the holes and the walls never come
// together (README, "Session 25"). Once a throw is tightened round the holes, the pierces
// between the two grips beyond it read one path instead: grip a → the knot's first passage K₁
// → the holes in node order → its last passage K₂ → grip b. Its excess over the thread there is
//     e = |K₁ − a| + |P₁ − K₁| + Σ |P_{k+1} − P_k| + |K₂ − P_n| + |b − K₂| + wrap − arc(a, b)
// where wrap is the thread the knot's turns take beyond the straight path K₁ → holes → K₂,
// taken as it tightened (a tight knot's turns keep their length; knotWrap). When e is within a
// link of 0 or above, every such pierce is taut, pulled by max(e, 0) towards its two neighbours
// on the path (the outer holes towards the knot). The grips and the arc between them do not
// change while the hands are still, so a knot that has drawn the walls together holds them.
// Held as the thread's leaders, such holes sent the hands' reach in a frame into the knot's few
// links before the walls could follow, and the knot broke 0.05 mm short of where it started.
// So they give way to the thread in its step (suture_solver.h, SutureWorld::yieldingBetween),
// and after it their points are where the thread left them: a hole whose point is off the
// tissue's (led) is pulled there by its spring, P_led + gain·pull(P_led), taut or not.
// The suture is inextensible and the tissue yields: gain ∈ (0, 1] is the fraction of the
// excess the tissue takes per frame (1 = at once; less damps the exchange).
//
// Two-way coupling (couplingSprings, used whenever the tissue solver honours soft terms):
// instead of moving the face's corners, the pierce point itself, P = u a + v b + w c, is
// tied by a zero-rest spring (point_spring.h) to where the thread wants it, P + gain·pull(P),
// with the thread's axial stiffness k = EA / L (CouplingParams::stiffness). The tissue's own
// stiffness then limits how far the point goes: a soft wall follows the thread, a stiff one
// (or one held by the other hand) stretches the thread instead, and the thread's tension is
// k times what is left, T = k |anchor − P| after the solve. Only the pierced point is pulled,
// so one pass through a wall no longer carries its whole face rigidly. A passive pierce (the
// rigid needle still passes through it) ties its point to the nearest point of the needle in
// the same way: the hole moves with the needle, so a wall pushed by a jaw or another pierce
// does not slide off the needle.
//
// Units: millimetres.

#include "microsim/sim/mesh/spring_model.h"
#include "microsim/sim/suture/suture_constraints.h"
#include "microsim/sim/suture/suture_model.h"

#include <optional>
#include <span>
#include <vector>

namespace microsim::sim::suture {

/// The axial stiffness of 10-0 nylon over a few millimetres of free thread (g/s², force per
/// mm): E ≈ 3 GPa (nylon 6 monofilament), d ≈ 22 µm (USP 10-0: 20–29 µm), so EA ≈ 1.1 N, and
/// over L ≈ 5 mm from the pierce to the hand EA / L ≈ 0.23 N/mm = 2.3e5 g/s².
inline constexpr double kNylon10_0Stiffness = 2.3e5;

struct CouplingParams {
  double gain = 1.0;  ///< fraction of the excess length the tissue takes per frame, (0, 1]
  double stiffness = kNylon10_0Stiffness;  ///< g/s²: the thread's pull per mm of excess left
};

/// The point u a + v b + w c of tissue face `face` (mm).
Vec3 tissuePoint(const SpringModel& tissue, const Points& tissueX, int face, const Vec3& barycentric);

/// Re-reads every pierce point from the tissue positions (3 by #tissue nodes).
void readPiercePoints(const SpringModel& tissue, const Points& tissueX, SutureState& state);

/// A knot tightened over a stitch (issue 19): the thread passes it at `first` and at `last`
/// (curve parameters, node index + fraction; first < last) with the stitch's holes between, and
/// its turns take `wrap` mm of the thread between those passages beyond the straight path from
/// the one through the holes to the other. A tight knot's turns keep their length, so `wrap`
/// is measured once, when it is tightened (knotWrap), and the passages follow the thread.
struct KnotOverStitch {
  double first = 0.0;
  double last = 0.0;
  double wrap = 0.0;
};

/// The thread between curve parameters first and last beyond the straight path from the one
/// through the active pierces between them to the other (mm).
double knotWrap(const SutureModel& model, const SutureState& state, double first, double last);

/// What the thread does at one pierce: pull(P) of the header essay (mm) and whether a side is
/// taut (then the pierce holds its face even with no excess left).
struct PierceTension {
  Vec3 pull = Vec3::Zero();
  bool taut = false;
};

/// The tension at each pierce, in SutureState::pierces order; passive pierces (on the
/// needle) are neither taut nor pulling.
std::vector<PierceTension> pierceTensions(const SutureModel& model, const SutureState& state,
                                          std::span<const Grip> grips,
                                          const std::optional<KnotOverStitch>& knot = std::nullopt);

/// The control-node targets that let the tissue solver follow the suture's pull (nodes sorted,
/// fixed nodes left out); empty when nothing pulls.
SpringControls couplingControls(const SpringModel& tissue, const Points& tissueX,
                                const SutureModel& model, const SutureState& state,
                                std::span<const Grip> grips, const CouplingParams& params = {},
                                const std::optional<KnotOverStitch>& knot = std::nullopt);

/// The two-way coupling: one spring per pierce that pulls or holds (SutureState::pierces
/// order among them), from the pierce point to P + gain·pull(P), or to the needle for a
/// passive pierce, of the thread's stiffness.
std::vector<PointSpring> couplingSprings(const SpringModel& tissue, const Points& tissueX,
                                         const SutureModel& model, const SutureState& state,
                                         std::span<const Grip> grips,
                                         const CouplingParams& params = {},
                                         const std::optional<KnotOverStitch>& knot = std::nullopt);

}  // namespace microsim::sim::suture
