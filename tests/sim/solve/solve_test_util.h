#pragma once
// Small spring models and measures shared by the solver tests.

#include "microsim/sim/mesh/lattice.h"
#include "microsim/sim/solve/solver.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace microsim::sim::testing {

/// A straight chain of `links` springs along x at unit spacing, node 0 fixed.
inline SpringModel chain(int links, double k = 10.0) {
  SpringModel model;
  for (int i = 0; i <= links; ++i) model.addNode(Vec3(i, 0, 0));
  for (int i = 0; i < links; ++i) model.addLink(i, i + 1, k);
  model.setFixed(0);
  model.finalize();
  return model;
}

/// Parameters each solver is tested with: the dynamic ones need damping to settle.
inline SolverParams paramsFor(const std::string& name) {
  SolverParams p;
  if (name == "rk4" || name == "implicit") p.damping = 6.0;
  return p;
}

/// The paper's protocol on an n³ box: the top middle node displaced by `d` in z.
inline SpringControls topPull(int n, double d) {
  SpringControls controls;
  const int top = latticeTopMiddle(n);
  const int middle = n / 2;  // the top middle node's grid index, rounded down for even n
  controls.add(top, Vec3(middle, middle, n - 1 + d));
  return controls;
}

/// Largest node distance between two position sets (mm).
inline double maxDistance(const Points& a, const Points& b) {
  return (a - b).colwise().norm().maxCoeff();
}

/// The equilibrium by the reference solver, from `start`.
inline SpringState referenceOf(const SpringModel& model, const SpringState& start,
                               const SpringControls& controls) {
  SpringState s = start;
  auto reference = makeSolver("reference");
  const SolveReport r = reference->solve(model, s, controls, {});
  EXPECT_EQ(r.status, SolveStatus::Converged);
  EXPECT_LE(r.residual, 1e-10);
  return s;
}

}  // namespace microsim::sim::testing
