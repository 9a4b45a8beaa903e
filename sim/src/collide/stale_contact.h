#pragma once
// When a tissue contact term (tissue_contact.h) no longer describes a contact.
//
// A term's normal and face point are frozen where the solve started, so it is a plane that
// moves with the face's corners. That serves while the motion is small. When the tissue
// springs far in one solve — a thread that held two walls together breaks, a pulled edge is
// let go — the face can sweep away from the node while the frozen plane still lies across
// the node's way home: the term pushes on a node that is nowhere near its face, and holds
// the wall bent (a stretch of 0.17 left in a wall with nothing on it) or folds it into
// itself step after step. Such a term is stale: it presses, yet the node is farther from the
// face's triangle than the reach within which contacts are watched. The scene drops it and
// solves again; a node that really ran into a face is found again as a violation.
//
// Units: mm.

#include "microsim/sim/mesh/point_spring.h"
#include "microsim/sim/mesh/spring_model.h"

namespace microsim::sim::collide {

/// Whether the node-against-face term `term` (weights 1, −u, −v, −w) presses at positions
/// x while its node lies more than `reach` from the triangle of its face.
bool contactIsStale(const PointSpring& term, const Points& x, double reach);

}  // namespace microsim::sim::collide
