#include "microsim/sim/solve/node_ordering.h"

namespace microsim::sim {

NodeOrdering computeNodeOrdering(const SpringModel& model, const std::vector<int>& seeds,
                                 const std::vector<unsigned char>& free) {
  const int n = model.nodeCount();
  NodeOrdering out;
  out.levelStart.push_back(0);
  std::vector<unsigned char> marked(static_cast<std::size_t>(n), 0);

  // level 0: the seeds (or the fixed nodes, or node 0)
  std::vector<int> frontier;
  for (int s : seeds)
    if (s >= 0 && s < n && !marked[s]) {
      marked[s] = 1;
      frontier.push_back(s);
    }
  if (frontier.empty())
    for (int i = 0; i < n; ++i)
      if (model.isFixed(i)) {
        marked[i] = 1;
        frontier.push_back(i);
      }
  if (frontier.empty() && n > 0) {
    marked[0] = 1;
    frontier.push_back(0);
    if (free[0]) {
      out.order.push_back(0);
      out.levelStart.push_back(1);
    }
  }

  // breadth-first waves; only levels holding free nodes are recorded
  std::vector<int> next;
  while (!frontier.empty()) {
    next.clear();
    for (int node : frontier)
      for (int li : model.linksOf(node)) {
        if (!model.link(li).alive) continue;
        const int other = model.otherEnd(li, node);
        if (marked[other]) continue;
        marked[other] = 1;
        next.push_back(other);
      }
    const std::size_t before = out.order.size();
    for (int node : next)
      if (free[node]) out.order.push_back(node);
    if (out.order.size() > before) out.levelStart.push_back(static_cast<int>(out.order.size()));
    frontier.swap(next);
  }

  // unreached free nodes: one last level
  const std::size_t before = out.order.size();
  for (int i = 0; i < n; ++i)
    if (!marked[i] && free[i]) out.order.push_back(i);
  if (out.order.size() > before) out.levelStart.push_back(static_cast<int>(out.order.size()));
  return out;
}

}  // namespace microsim::sim
