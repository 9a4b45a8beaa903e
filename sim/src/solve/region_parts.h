#pragma once
// The parts of a solve's region that nothing couples: the nodes that alive links and soft terms
// (point_spring.h) join, directly or through other nodes of the region. Newton solves each part
// as a problem of its own (newton_solver.cpp, "Parts"): their Hessian is block diagonal and
// their energies add up. The links' sets change only with the topology, the soft terms' every
// step, so the two are found apart: linkSets once, regionParts on a copy of them every solve.
//
// Region indices: the region is a list of node indices; `local` gives, per node of the model,
// its index in that list or −1.

#include "microsim/sim/mesh/point_spring.h"
#include "microsim/sim/mesh/spring_model.h"

#include <vector>

namespace microsim::sim::detail {

/// Union–find over the items 0 .. n − 1, every set's root its lowest item.
class DisjointSets {
 public:
  /// Every item a set of its own.
  void reset(int n);
  /// Starts from sets found earlier: per item its root (as roots() gave them).
  void assign(const std::vector<int>& roots) { parent_ = roots; }
  /// The root of a's set (halving the path on the way).
  int root(int a);
  /// Joins the sets of a and b.
  void join(int a, int b);
  /// Per item the root of its set.
  std::vector<int> roots();

 private:
  std::vector<int> parent_;
};

/// Per region index the root of its set when the region's alive links join their ends.
std::vector<int> linkSets(const SpringModel& model, const std::vector<int>& region,
                          const std::vector<int>& local);

/// The region's parts: the sets of `linkRoots` (linkSets) joined further by the nodes of each
/// soft term, each part's nodes in region order, the parts in the order of their first node.
void regionParts(const std::vector<int>& linkRoots, const std::vector<PointSpring>& springs,
                 const std::vector<int>& region, const std::vector<int>& local,
                 std::vector<std::vector<int>>& parts);

}  // namespace microsim::sim::detail
