// When a frozen tissue contact term stops describing a contact (collide/stale_contact.h): one
// face in z = 0 (normal +z), a node against it, the term frozen with the node just above the
// face; then the node is put where a solve might have carried it.
#include "collide/stale_contact.h"

#include <gtest/gtest.h>

namespace microsim::sim::collide {
namespace {

constexpr double kStaleReach = 0.1;  // mm, the scenes' contact reach

/// Nodes 0–2 the face (0, 0, 0), (1, 0, 0), (0, 1, 0); node 3 the node against it.
Points staleFace(const Vec3& node) {
  Points x(3, 4);
  x.col(0) = Vec3(0, 0, 0);
  x.col(1) = Vec3(1, 0, 0);
  x.col(2) = Vec3(0, 1, 0);
  x.col(3) = node;
  return x;
}

/// The term as tissue_contact.h freezes it: node 3 against the face point under (0.25, 0.25).
PointSpring staleTerm() {
  PointSpring s;
  s.nodes = {3, 0, 1, 2};
  s.weights = {1.0, -0.5, -0.25, -0.25};
  s.normal = Vec3::UnitZ();
  s.gap = 0.01;
  s.k = 100.0;
  return s;
}

TEST(StaleContact, APressedTermOverItsFaceIsAContact) {
  EXPECT_FALSE(contactIsStale(staleTerm(), staleFace(Vec3(0.25, 0.25, -0.005)), kStaleReach));
}

TEST(StaleContact, ATermThatDoesNotPressIsNeverStale) {
  EXPECT_FALSE(contactIsStale(staleTerm(), staleFace(Vec3(3.0, 0.25, 0.2)), kStaleReach));
}

// The face's frozen plane still lies across the node's way, but the node is 1.5 mm beside
// the face: the term pushes on nothing.
TEST(StaleContact, APressedTermWhoseNodeLeftTheFaceIsStale) {
  EXPECT_TRUE(contactIsStale(staleTerm(), staleFace(Vec3(2.5, 0.25, -0.005)), kStaleReach));
}

// Just past the face's edge, within reach, it is still a contact (the node slides over it).
TEST(StaleContact, APressedTermJustPastTheFacesEdgeStillHolds) {
  EXPECT_FALSE(contactIsStale(staleTerm(), staleFace(Vec3(0.8, 0.25, -0.005)), kStaleReach));
}

}  // namespace
}  // namespace microsim::sim::collide
