#pragma once
// Follow-the-leader (Brown et al. 2002 §4, Fig. 6), the paper's suture motion, as stateless
// kernels on the chain's positions.
//
// The suture "can stretch minimally if at all", so it is not a mass–spring: its links are
// rigid and its motion is computed from the nodes that something constrains (leaders). When
// a leader N_i moves from x_i,old to x_i,new, its neighbour is placed at the link's rest
// distance d from x_i,new on the line towards its own old position:
//     x_{i+1,new} = x_{i,new} + d · (x_{i+1,old} − x_{i,new}) / |x_{i+1,old} − x_{i,new}|,
// and so on outward, up and down the chain, until the next leader or the chain's end.
// Between two leaders N_i and N_j (i < j) the passes from both sides are computed over the
// same old positions and averaged: x_k = (A_k + B_k)/2 for i < k < j, A from N_i upward,
// B from N_j downward.
//
// Invariants: outside the spans between two leaders every link keeps its rest length exactly
// (up to rounding); inside such a span the averaged positions keep them only when both
// passes agree, i.e. the span is slack enough, which is the paper's stretch artefact the
// direct solver (chain_projection.h) removes. If a node's old position coincides with its
// new predecessor the line is undefined; the previous link's direction is used instead,
// and +x for the first one.
//
// Units: millimetres. Positions are 3 by (N + 1).

#include "microsim/sim/suture/suture_model.h"

#include <span>
#include <vector>

namespace microsim::sim::suture {

/// A constrained node and where it must be (mm).
struct Leader {
  int node = 0;
  Vec3 position = Vec3::Zero();
};

/// Moves nodes from + s, from + 2s, ... (s = ±1, the sign of stop − from) up to and excluding
/// `stop`, each to its rest distance from its already-moved predecessor on the line towards
/// its old position (the column of x it still holds). `rest[l]` is link l's length.
void followChain(Points& x, std::span<const double> rest, int from, int stop);

/// The paper's move of one piece [first, last] of the chain: sets each leader's node to its
/// position, follows outward to the piece's ends and averages the two passes between
/// consecutive leaders. `leaders` must be sorted by node, unique, inside the piece. With no
/// leaders nothing moves.
void followTheLeader(Points& x, std::span<const double> rest, int first, int last,
                     std::span<const Leader> leaders);

/// followTheLeader on every piece of the chain; leaders sorted by node, unique.
void followTheLeader(const SutureModel& model, Points& x, const std::vector<std::uint8_t>& alive,
                     std::span<const Leader> leaders);

/// The outward half of followTheLeader: sets every leader's node and follows from the first
/// and last leader of each piece to its ends; nodes between leaders keep their positions (the
/// direct solver's predictor, see suture_solver.h).
void followOutward(const SutureModel& model, Points& x, const std::vector<std::uint8_t>& alive,
                   std::span<const Leader> leaders);

}  // namespace microsim::sim::suture
