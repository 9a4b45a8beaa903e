#include "microsim/sim/mesh/spring_model.h"

#include <algorithm>
#include <cassert>

namespace microsim::sim {

int SpringModel::addNode(const Vec3& position, double mass, double damping) {
  const int index = nodeCount();
  if (index == rest_.cols()) rest_.conservativeResize(3, std::max<Eigen::Index>(16, 2 * rest_.cols()));
  rest_.col(index) = position;
  mass_.push_back(mass);
  damping_.push_back(damping);
  role_.push_back(NodeRole::Free);
  finalized_ = false;
  return index;
}

int SpringModel::addLink(int a, int b, double k, double rest, StiffnessLaw law, double gain) {
  assert(a >= 0 && a < nodeCount() && b >= 0 && b < nodeCount());
  Link link;
  link.a = a;
  link.b = b;
  link.k = k;
  link.rest = rest >= 0.0 ? rest : (rest_.col(a) - rest_.col(b)).norm();
  link.law = law;
  link.gain = gain;
  links_.push_back(link);
  ++aliveLinks_;
  finalized_ = false;
  return linkCount() - 1;
}

void SpringModel::setFixed(int node, bool fixed) {
  role_[node] = fixed ? NodeRole::Fixed : NodeRole::Free;
}

bool SpringModel::removeLink(int link) {
  if (link < 0 || link >= linkCount()) return false;
  if (links_[link].alive) {
    links_[link].alive = false;
    --aliveLinks_;
  }
  return true;
}

void SpringModel::finalize() {
  // counting sort of link ends by node: CSR adjacency in link order
  const int n = nodeCount();
  adjacencyStart_.assign(n + 1, 0);
  for (const Link& l : links_) {
    ++adjacencyStart_[l.a + 1];
    ++adjacencyStart_[l.b + 1];
  }
  for (int i = 0; i < n; ++i) adjacencyStart_[i + 1] += adjacencyStart_[i];
  adjacency_.assign(adjacencyStart_[n], 0);
  std::vector<int> cursor(adjacencyStart_.begin(), adjacencyStart_.end() - 1);
  for (int li = 0; li < linkCount(); ++li) {
    adjacency_[cursor[links_[li].a]++] = li;
    adjacency_[cursor[links_[li].b]++] = li;
  }
  finalized_ = true;
}

std::vector<int> SpringModel::fixedNodes() const {
  std::vector<int> out;
  for (int i = 0; i < nodeCount(); ++i)
    if (role_[i] == NodeRole::Fixed) out.push_back(i);
  return out;
}

SpringState SpringState::atRest(const SpringModel& model) {
  SpringState s;
  s.x = model.restPositions();
  s.v = Points::Zero(3, model.nodeCount());
  return s;
}

void SpringControls::add(int node, const Vec3& target) {
  nodes.push_back(node);
  targets.conservativeResize(3, size());
  targets.col(size() - 1) = target;
}

}  // namespace microsim::sim
