#pragma once
// Several meshes in one model: a scene with two vessel ends, or a vessel and a pad, is
// one SpringModel whose nodes, links and triangles are the parts' in order, so one
// solver sees the whole scene.

#include "microsim/sim/mesh/spring_model.h"

namespace microsim::sim {

/// Appends `part` to `into`: nodes (position, mass, damping, fixed role), links (every
/// field, dead ones stay dead) and triangles, with node indices shifted by the number
/// of nodes `into` had. Returns that shift. `into` is left unfinalized.
int appendModel(SpringModel& into, const SpringModel& part);

}  // namespace microsim::sim
