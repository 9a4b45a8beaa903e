#include "solve/region_parts.h"

#include <algorithm>
#include <cstddef>
#include <numeric>

namespace microsim::sim::detail {

void DisjointSets::reset(int n) {
  parent_.resize(static_cast<std::size_t>(n));
  std::iota(parent_.begin(), parent_.end(), 0);
}

int DisjointSets::root(int a) {
  while (parent_[static_cast<std::size_t>(a)] != a) {
    const int up = parent_[static_cast<std::size_t>(parent_[static_cast<std::size_t>(a)])];
    parent_[static_cast<std::size_t>(a)] = up;
    a = up;
  }
  return a;
}

void DisjointSets::join(int a, int b) {
  a = root(a);
  b = root(b);
  if (a != b) parent_[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
}

std::vector<int> DisjointSets::roots() {
  std::vector<int> out(parent_.size());
  for (std::size_t a = 0; a < parent_.size(); ++a) out[a] = root(static_cast<int>(a));
  return out;
}

std::vector<int> linkSets(const SpringModel& model, const std::vector<int>& region,
                          const std::vector<int>& local) {
  DisjointSets sets;
  const int m = static_cast<int>(region.size());
  sets.reset(m);
  for (int r = 0; r < m; ++r)
    for (int li : model.linksOf(region[static_cast<std::size_t>(r)])) {
      const int s =
          local[static_cast<std::size_t>(model.otherEnd(li, region[static_cast<std::size_t>(r)]))];
      if (model.link(li).alive && s >= 0) sets.join(r, s);
    }
  return sets.roots();
}

void regionParts(const std::vector<int>& linkRoots, const std::vector<PointSpring>& springs,
                 const std::vector<int>& region, const std::vector<int>& local,
                 std::vector<std::vector<int>>& parts) {
  DisjointSets sets;
  sets.assign(linkRoots);
  for (const PointSpring& sp : springs) {
    int first = -1;
    for (int k = 0; k < sp.size(); ++k) {
      const int s = local[static_cast<std::size_t>(sp.nodes[static_cast<std::size_t>(k)])];
      if (s < 0) continue;
      if (first < 0)
        first = s;
      else
        sets.join(first, s);
    }
  }
  // a set's root (its lowest index) comes before the rest of it: it opens the next part
  const std::vector<int> roots = sets.roots();
  std::vector<std::size_t> partOfRoot(roots.size(), 0);
  std::size_t count = 0;
  for (std::size_t r = 0; r < roots.size(); ++r) {
    const auto top = static_cast<std::size_t>(roots[r]);
    if (top == r) {
      if (parts.size() <= count) parts.emplace_back();
      parts[count].clear();
      partOfRoot[top] = count++;
    }
    parts[partOfRoot[top]].push_back(region[r]);
  }
  parts.resize(count);
}

}  // namespace microsim::sim::detail
