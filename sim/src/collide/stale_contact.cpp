#include "collide/stale_contact.h"

#include "microsim/sim/collide/point_triangle.h"

namespace microsim::sim::collide {

bool contactIsStale(const PointSpring& term, const Points& x, double reach) {
  if (term.size() != 4 || pointSpringForce(term, pointSpringOffset(term, x)).isZero(0.0)) return false;
  const PointTriangleClosest q = closestPointTriangle(x.col(term.nodes[0]), x.col(term.nodes[1]),
                                                      x.col(term.nodes[2]), x.col(term.nodes[3]));
  return q.distance > reach;
}

}  // namespace microsim::sim::collide
