#include "solve/region_parts.h"

#include <gtest/gtest.h>

namespace microsim::sim::detail {
namespace {

// two chains of three links, 0–3 and 4–7, neither fixed
SpringModel twoChains() {
  SpringModel model;
  for (int i = 0; i < 8; ++i) model.addNode(Vec3(i % 4, i < 4 ? 0.0 : 1.0, 0.0));
  for (int c = 0; c < 2; ++c)
    for (int i = 0; i < 3; ++i) model.addLink(4 * c + i, 4 * c + i + 1, 1.0);
  model.finalize();
  return model;
}

std::vector<int> localOf(const std::vector<int>& region, int nodes) {
  std::vector<int> local(static_cast<std::size_t>(nodes), -1);
  for (std::size_t r = 0; r < region.size(); ++r)
    local[static_cast<std::size_t>(region[r])] = static_cast<int>(r);
  return local;
}

PointSpring between(int a, int b) {
  PointSpring sp;
  sp.nodes = {a, b, -1, -1};
  sp.weights = {1.0, -1.0, 0.0, 0.0};
  sp.k = 1.0;
  return sp;
}

TEST(DisjointSets, EverySetsRootIsItsLowestItem) {
  DisjointSets sets;
  sets.reset(6);
  sets.join(4, 2);
  sets.join(5, 4);
  sets.join(3, 1);
  EXPECT_EQ(sets.roots(), (std::vector<int>{0, 1, 2, 1, 2, 2}));
  sets.join(5, 3);
  EXPECT_EQ(sets.roots(), (std::vector<int>{0, 1, 1, 1, 1, 1}));
  EXPECT_EQ(sets.root(5), 1);
}

TEST(RegionParts, LinksMakeOnePartOfEachPieceInTheOrderOfTheirFirstNode) {
  const SpringModel model = twoChains();
  const std::vector<int> region{5, 1, 6, 2, 0, 7};  // nodes 3 and 4 held
  const std::vector<int> local = localOf(region, model.nodeCount());
  std::vector<std::vector<int>> parts;
  regionParts(linkSets(model, region, local), {}, region, local, parts);
  // 5–6–7 is one piece; of the other, 0–1–2 (3, outside the region, joins nothing)
  EXPECT_EQ(parts, (std::vector<std::vector<int>>{{5, 6, 7}, {1, 2, 0}}));
}

TEST(RegionParts, ADeadLinkSplitsAPieceAndASoftTermJoinsTwo) {
  SpringModel model = twoChains();
  model.removeLink(1);  // 1–2
  std::vector<int> region(8);
  for (int i = 0; i < 8; ++i) region[static_cast<std::size_t>(i)] = i;
  const std::vector<int> local = localOf(region, model.nodeCount());
  const std::vector<int> links = linkSets(model, region, local);
  std::vector<std::vector<int>> parts;
  regionParts(links, {}, region, local, parts);
  EXPECT_EQ(parts, (std::vector<std::vector<int>>{{0, 1}, {2, 3}, {4, 5, 6, 7}}));
  // a soft term on nodes 3 and 5 joins the last two; one on a node outside the region joins none
  regionParts(links, {between(3, 5)}, region, local, parts);
  EXPECT_EQ(parts, (std::vector<std::vector<int>>{{0, 1}, {2, 3, 4, 5, 6, 7}}));
  const std::vector<int> part{0, 1, 4, 5};
  const std::vector<int> partLocal = localOf(part, model.nodeCount());
  regionParts(linkSets(model, part, partLocal), {between(2, 4)}, part, partLocal, parts);
  EXPECT_EQ(parts, (std::vector<std::vector<int>>{{0, 1}, {4, 5}}));
}

}  // namespace
}  // namespace microsim::sim::detail
