#pragma once
// A chain's node positions (3 by n, mm) from a list of points, for tests that lay a thread by hand.
#include "microsim/sim/mesh/spring_model.h"

#include <vector>

namespace microsim::testing {

inline sim::Points chainOf(const std::vector<sim::Vec3>& nodes) {
  sim::Points x(3, static_cast<Eigen::Index>(nodes.size()));
  for (std::size_t i = 0; i < nodes.size(); ++i) x.col(static_cast<Eigen::Index>(i)) = nodes[i];
  return x;
}

}  // namespace microsim::testing
