#pragma once
// NODE-ORDERING and the wave-order cutout of Brown et al. 2002 §3.3.2.
//
// QSS relaxes the nodes one at a time, in place (Gauss–Seidel): each update already sees
// the new positions of the nodes updated before it. The order matters. Processing the
// nodes in breadth-first "waves" from the displaced control nodes carries a pull across
// the whole mesh in a single sweep: level 1 (the neighbours of the pulled nodes) moves
// first, level 2 then sees level 1's new positions, and so on outward.
//
//   level 0 = the displaced control nodes (the nodes tools hold);
//   level k = the unmarked neighbours (through alive links) of level k − 1;
//   order I = the free nodes by increasing level (within a level, in breadth-first
//             discovery order: deterministic).
//
// The order depends only on the topology and on the set of displaced control nodes, so a
// solver recomputes it only when one of those changes (a grab, a release, a cut).
//
// The cutout: during one sweep, when every node of some level k moved by less than ε,
// the wave has died out there and the sweep stops before level k + 1. The work per
// sweep then follows the deforming region, not the mesh. With ε = 0 no level ever
// qualifies (a move is never < 0), so the cutout changes nothing, bit for bit.
//
// Seeds when no control node pulls: the fixed nodes (a mesh sagging under gravity
// relaxes outward from its clamps); when there are none either, node 0. Free nodes not
// connected to any seed form one last level, by index.

#include "microsim/sim/mesh/spring_model.h"

#include <vector>

namespace microsim::sim {

struct NodeOrdering {
  std::vector<int> order;       ///< the free nodes in wave order (the paper's I)
  std::vector<int> levelStart;  ///< order[levelStart[k] .. levelStart[k + 1]) is level k + 1;
                                ///< size = #levels + 1
  int levelCount() const { return static_cast<int>(levelStart.size()) - 1; }
};

/// NODE-ORDERING from `seeds` over alive links. `free` holds one byte per node, 1 for the
/// nodes to order (neither fixed nor controlled); seeds and other constrained nodes are
/// traversed but not listed.
NodeOrdering computeNodeOrdering(const SpringModel& model, const std::vector<int>& seeds,
                                 const std::vector<unsigned char>& free);

}  // namespace microsim::sim
