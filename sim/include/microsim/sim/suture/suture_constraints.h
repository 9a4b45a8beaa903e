#pragma once
// The suture's constraints (Brown et al. 2002 §4) and what they do beyond holding nodes:
// sliding through soft constraints, breaking between hard ones, and the rigid needle.
//
// Hard constraints are grips: a forceps holds the point a `fraction` along the link from node
// `node` to node + 1 at `position` (fraction 0: the node itself). A grip on the needle (a
// needle link, or the swage node itself) holds the rigid needle: with `oriented` in the pose
// `rotation`, and every needle node is posed from the grip point, so a needle grasped between
// two nodes turns about that point. A grip on a thread node is a ball joint (the thread turns
// about it); a grip between two thread nodes clamps the link it lies on: both nodes are held,
// the link along `direction` through the grip point (the jaws close across the thread and it
// cannot turn between them; two held nodes could not turn about a point between them anyway).
// Where the rules below speak of a grip's node, a grip between nodes holds both (see
// pieceConstraints). Soft constraints are pierces (suture_model.h): the suture passes through
// a point on a tissue face.
//
// Path order. The tip makes the pierces one after another and the suture follows it through
// them, so along the chain (node index, from the tip) each pierce lies nearer the tip than
// those made before it, and it must stay so: a pierce never passes another. A thread node
// holds one pierce; pierces the needle still carries may share a needle node (on one node, the
// later-made is the nearer the tip).
//
// Passive pierces. A pierce on a needle node (node < swage) is passive: the rigid needle
// carries the suture through it, and `node` follows the needle node nearest the point (the
// nearer end of the nearest needle segment), but never onto or past the node of the pierce
// ahead of it in path order. When it reaches the swage it is active. Once the needle has left
// the point — drawn back out of the hole, or moved off it — by more than
// SutureDef::pierceReleaseDistance, the thread will never pass there: the pierce is removed
// (SutureEventKind::Released). The needle is a polyline through its nodes, which lies within
// R(1 − cos(θ/2)) of the true arc (θ the angle of one needle link; 0.009 mm for the scenes'
// 0.8 mm needle in 8 links), well inside the default 0.05 mm.
//
// Sliding. Around each active pierce P at node c, look at its two sides: the neighbouring
// constraint Q (grip or pierce, or the end of turns wound on a forceps' jaws: the turns hold
// the thread by their friction, so the side a hole can draw from ends where they begin; measured
// to the grip beyond them, a long end wound round the jaws read as slack, its straight span far
// short of its arc, and the tail was drawn 8 links through the stitch as the jaws drew it
// back) on each side, or the chain's free end. A side's stretch is
//     σ = |P − Q| / arc(c, q)       (0 towards a free end, which can always feed thread)
// — the straight distance the side must span over the rest length it has. A grip on a needle
// node holds the needle rigid up to the swage, so on that side Q is the swage where the needle
// puts it, q the swage. When one side is taut (σ > 1 + slideTolerance) and tighter than the
// other, the suture slides through the pierce one node towards the slack side (the taut side
// gains a link), and again while that lowers max(σ_left, σ_right), but never past a
// neighbouring constraint's node, nor below the swage: the rigid needle cannot slide back
// through a pierce. The pierce point stays on the tissue; only `node` changes. A pierce whose
// node would slide past a free end has let the suture go (SutureEventKind::PulledOut).
//
// Breaking. Between two consecutive grips a and b of one piece, the path the suture must
// span runs through the pierce points between them: L = Σ |P_k − P_{k+1}|. When
// L > arc(a, b)·(1 + breakStretch) the suture breaks (SutureEventKind::Break) at the link of
// a..b that is stretched most (the lowest index on ties), leaving two free pieces.
//
// Units: millimetres, seconds.

#include "microsim/sim/suture/suture_model.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace microsim::sim::suture {

/// A hard constraint: a forceps holding a point of the chain (header essay).
struct Grip {
  int node = 0;
  Vec3 position = Vec3::Zero();                        ///< mm: where the held point must be
  bool oriented = false;                               ///< holds the needle's pose too
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  ///< needle frame → world (oriented)
  /// Along the link node → node + 1, in [0, 1): the held point is (1 − f) x_node + f x_{node+1}.
  double fraction = 0.0;
  /// Between two thread nodes: the held link's direction (unit, node → node + 1).
  Vec3 direction = Vec3::Zero();
};

/// True when `grip` holds the rigid needle: it lies on a needle link or on the swage node.
bool gripHoldsNeedle(const SutureModel& model, const Grip& grip);
/// The chain point `grip` holds, at positions x (mm).
Vec3 gripPoint(const Points& x, const Grip& grip);
/// Where a grip between two thread nodes puts them, its point at `point` and the link along
/// the unit `direction`: [0] node, [1] node + 1 (mm).
std::array<Vec3, 2> clampedLinkEnds(const SutureModel& model, const Grip& grip, const Vec3& point,
                                    const Vec3& direction);

enum class SutureEventKind : std::uint8_t {
  Break,      ///< a link broke between two hard constraints (link = the broken link)
  PulledOut,  ///< the suture slid off its end through a pierce (pierce = its index before removal)
  Released,   ///< the needle left a passive pierce before the thread reached it (pierce = its
              ///< index before removal): the suture does not pass there
};

struct SutureEvent {
  SutureEventKind kind = SutureEventKind::Break;
  int link = -1;     ///< Break: the broken link
  int pierce = -1;   ///< PulledOut, Released: its index in SutureState::pierces before removal
  double time = 0.0; ///< s
};

/// A constraint on the chain in node order: a grip (hard) or an active pierce (soft).
struct ChainConstraint {
  int node = 0;
  Vec3 position = Vec3::Zero();
  bool hard = false;
  int source = -1;  ///< index into the grips or the pierces
  /// The end of turns wound on a forceps' jaws (hard): it bounds a side as a grip does, but the
  /// turns slide on the jaws, so thread may be drawn from them through the holes beside them.
  bool wound = false;
};

/// Grips and active pierces of the piece [first, last], sorted by node (a grip wins a tie). A
/// grip on a node gives one hard constraint at its position; a grip between two nodes gives
/// two, at both nodes where x has them (after a substep: where the grip put them).
std::vector<ChainConstraint> pieceConstraints(const SutureModel& model, const SutureState& state,
                                              std::span<const Grip> grips, const Piece& piece);

/// The rules of the header essay: passive (needle) pierces tracked in path order, released
/// once the needle has left them; active pierces slid; released and pulled-out pierces removed
/// (an event each, highest index first). Returns the number of one-node slides.
/// `wound`: runs of nodes [first, last] wound on a forceps' jaws (suture_contact.h, Sleeve),
/// whose ends bound the sides as grips do.
int slidePierces(const SutureModel& model, SutureState& state, std::span<const Grip> grips,
                 double slideTolerance, std::vector<SutureEvent>& events,
                 std::span<const std::array<int, 2>> wound = {});

/// The breaking rule of the header essay: the link that breaks, if any (the first pair of
/// grips over the threshold in node order).
std::optional<int> findBreak(const SutureModel& model, const SutureState& state,
                             std::span<const Grip> grips);

/// Restores the needle's rest shape about node `anchor` (a needle node or the swage): with a
/// rotation, x_k = x_anchor + R (r_k − r_anchor); without, R is the best fit (Kabsch) of the
/// rest shape to the current needle nodes. No-op without a needle.
void rigidifyNeedle(const SutureModel& model, Points& x, int anchor,
                    const Eigen::Matrix3d* rotation = nullptr);

/// The needle's current rotation (needle frame → world), best fit to its nodes.
Eigen::Matrix3d needleRotation(const SutureModel& model, const Points& x);

}  // namespace microsim::sim::suture
