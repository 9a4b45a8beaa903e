#include "microsim/sim/mesh/merge.h"

namespace microsim::sim {

int appendModel(SpringModel& into, const SpringModel& part) {
  const int offset = into.nodeCount();
  for (int i = 0; i < part.nodeCount(); ++i) {
    const int n = into.addNode(part.restPositions().col(i), part.mass(i), part.damping(i));
    if (part.isFixed(i)) into.setFixed(n);
  }
  for (const Link& l : part.links()) {
    const int li = into.addLink(l.a + offset, l.b + offset, l.k, l.rest, l.law, l.gain);
    if (!l.alive) into.removeLink(li);
  }
  for (const auto& t : part.triangles())
    into.addTriangle(t[0] + offset, t[1] + offset, t[2] + offset);
  return offset;
}

}  // namespace microsim::sim
