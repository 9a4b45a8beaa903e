#include "solve/solve_support.h"

#include <algorithm>
#include <cmath>

namespace microsim::sim::detail {

bool allFinite(const Points& p) {
  const double* d = p.data();
  for (Eigen::Index i = 0; i < p.size(); ++i)
    if (!std::isfinite(d[i])) return false;
  return true;
}

bool validInput(const SpringModel& model, const SpringState& state,
                const SpringControls& controls) {
  const int n = model.nodeCount();
  if (!model.finalized()) return false;
  if (state.x.cols() != n || state.v.cols() != n) return false;
  if (!allFinite(state.x) || !allFinite(state.v)) return false;
  if (!model.gravity.allFinite()) return false;
  if (controls.targets.cols() != controls.size()) return false;
  for (int c : controls.nodes)
    if (c < 0 || c >= n) return false;
  for (const PointSpring& s : controls.springs) {
    if (!(s.k >= 0.0) || !std::isfinite(s.k) || !std::isfinite(s.gap) || !s.anchor.allFinite() ||
        !s.normal.allFinite() || s.size() == 0)
      return false;
    for (int k = 0; k < s.size(); ++k) {
      const int node = s.nodes[static_cast<std::size_t>(k)];
      if (node < 0 || node >= n || !std::isfinite(s.weights[static_cast<std::size_t>(k)])) return false;
    }
  }
  return allFinite(controls.targets);
}

void applyControls(const SpringModel& model, SpringState& state, const SpringControls& controls) {
  for (int c = 0; c < controls.size(); ++c) {
    const int node = controls.nodes[c];
    if (model.isFixed(node)) continue;
    state.x.col(node) = controls.targets.col(c);
    state.v.col(node).setZero();
  }
  for (int i = 0; i < model.nodeCount(); ++i)
    if (model.isFixed(i)) state.v.col(i).setZero();
}

std::vector<int> activeControlNodes(const SpringModel& model, const SpringControls& controls) {
  std::vector<int> nodes;
  for (int c : controls.nodes)
    if (!model.isFixed(c)) nodes.push_back(c);
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

double maxStiffness(const SpringModel& model) {
  double k = 0.0;
  for (const Link& link : model.links())
    if (link.alive) k = std::max(k, link.k);
  return k;
}

}  // namespace microsim::sim::detail
