#pragma once
// Triangle against triangle (prodding: face against face; tissue self-contact).
//
// Two closed triangles A, B intersect iff an edge of one meets the other (segment_triangle.h).
// Proof sketch: if the planes differ, A ∩ B is the overlap of the two intervals A ∩ L and
// B ∩ L on the common line L; an end of that overlap ends one interval, so it lies on an edge
// of A or B and inside the other. If coplanar, either the boundaries cross or one triangle
// holds the other, whose edges then lie inside it. A zero-area triangle is its edges.
// Before the six edge tests, the usual plane rejection (Möller 1997): all corners of A
// strictly on one side of B's plane, or the converse, means no contact.
//
// Distance: 0 when they intersect, else the least of the nine edge–edge distances and the six
// corner–face distances (the closest pair of two disjoint convex polygons is one of those).
//
// Units: millimetres.

#include <Eigen/Core>

namespace microsim::sim::collide {

bool trianglesIntersect(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                        const Eigen::Vector3d& p2, const Eigen::Vector3d& q0,
                        const Eigen::Vector3d& q1, const Eigen::Vector3d& q2);

/// Smallest distance (mm) between the closed triangles; 0 when they intersect.
double triangleTriangleDistance(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                const Eigen::Vector3d& p2, const Eigen::Vector3d& q0,
                                const Eigen::Vector3d& q1, const Eigen::Vector3d& q2);

}  // namespace microsim::sim::collide
