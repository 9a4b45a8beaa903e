#include "microsim/sim/mesh/spring_model.h"

#include <gtest/gtest.h>

namespace microsim::sim {
namespace {

SpringModel triangle() {
  SpringModel m;
  m.addNode({0, 0, 0});
  m.addNode({3, 0, 0});
  m.addNode({0, 4, 0}, 2.0, 0.5);
  m.addLink(0, 1, 10.0);
  m.addLink(1, 2, 20.0);
  m.addLink(2, 0, 30.0, 1.5);
  m.addTriangle(0, 1, 2);
  m.finalize();
  return m;
}

TEST(SpringModel, RestLengthDefaultsToInitialDistance) {
  const SpringModel m = triangle();
  EXPECT_DOUBLE_EQ(m.link(0).rest, 3.0);
  EXPECT_DOUBLE_EQ(m.link(1).rest, 5.0);
  EXPECT_DOUBLE_EQ(m.link(2).rest, 1.5);
  EXPECT_DOUBLE_EQ(m.mass(2), 2.0);
  EXPECT_DOUBLE_EQ(m.damping(2), 0.5);
}

TEST(SpringModel, AdjacencyListsEveryIncidentLinkOnce) {
  const SpringModel m = triangle();
  for (int node = 0; node < m.nodeCount(); ++node) {
    const auto links = m.linksOf(node);
    ASSERT_EQ(links.size(), 2u) << "node " << node;
    for (int li : links) {
      const Link& l = m.link(li);
      EXPECT_TRUE(l.a == node || l.b == node);
      EXPECT_NE(m.otherEnd(li, node), node);
    }
  }
}

TEST(SpringModel, RemovingALinkKeepsIndicesAndAdjacency) {
  SpringModel m = triangle();
  EXPECT_TRUE(m.removeLink(1));
  EXPECT_TRUE(m.removeLink(1));  // idempotent
  EXPECT_FALSE(m.removeLink(7));
  EXPECT_EQ(m.linkCount(), 3);
  EXPECT_EQ(m.aliveLinkCount(), 2);
  EXPECT_FALSE(m.link(1).alive);
  EXPECT_TRUE(m.finalized());
  EXPECT_EQ(m.linksOf(1).size(), 2u);
}

TEST(SpringModel, FixedNodesAndRestState) {
  SpringModel m = triangle();
  m.setFixed(2);
  EXPECT_EQ(m.fixedNodes(), std::vector<int>{2});
  const SpringState s = SpringState::atRest(m);
  EXPECT_EQ(s.x.cols(), 3);
  EXPECT_TRUE(s.x.isApprox(m.restPositions()));
  EXPECT_TRUE(s.v.isZero());
}

TEST(SpringControls, AddKeepsNodesAndTargetsInStep) {
  SpringControls c;
  c.add(4, {1, 2, 3});
  c.add(9, {-1, 0, 0});
  ASSERT_EQ(c.size(), 2);
  EXPECT_EQ(c.nodes[1], 9);
  EXPECT_EQ(c.targets.col(0), Vec3(1, 2, 3));
}

}  // namespace
}  // namespace microsim::sim
