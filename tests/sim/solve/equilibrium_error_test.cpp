// equilibriumError: zero for a converged state, the known lag for a state moved off its
// equilibrium, and the ratio against the largest control displacement from rest.
#include "microsim/sim/solve/equilibrium_error.h"

#include "solve_test_util.h"

#include <gtest/gtest.h>

namespace microsim::sim {
namespace {

using testing::chain;
using testing::referenceOf;

/// The chain's last node pulled `pull` mm along +x, and a second control held at rest.
SpringControls equilibriumErrorChainPull(const SpringModel& model, double pull) {
  SpringControls controls;
  const int last = model.nodeCount() - 1;
  controls.add(last, model.restPositions().col(last) + Vec3(pull, 0, 0));
  return controls;
}

TEST(EquilibriumError, ConvergedStateHasNoError) {
  const SpringModel model = chain(4);
  const SpringControls controls = equilibriumErrorChainPull(model, 1.0);
  const SpringState converged = referenceOf(model, SpringState::atRest(model), controls);

  const EquilibriumError e = equilibriumError(model, converged, controls);
  EXPECT_TRUE(e.converged);
  EXPECT_NEAR(e.controlDisplacement, 1.0, 1e-12);
  EXPECT_LT(e.maxDistance, 1e-8);
  EXPECT_LT(e.ratioPercent, 1e-6);
}

TEST(EquilibriumError, LaggingStateGivesItsLag) {
  const SpringModel model = chain(4);
  const SpringControls controls = equilibriumErrorChainPull(model, 2.0);
  SpringState lagging = referenceOf(model, SpringState::atRest(model), controls);
  const Points equilibrium = lagging.x;
  // one free node 0.1 mm off its equilibrium, sideways: 5 % of the 2 mm pull
  lagging.x(1, 2) += 0.1;

  const EquilibriumError e = equilibriumError(model, lagging, controls);
  EXPECT_TRUE(e.converged);
  EXPECT_NEAR(e.controlDisplacement, 2.0, 1e-12);
  EXPECT_NEAR(e.maxDistance, 0.1, 1e-8);
  EXPECT_NEAR(e.ratioPercent, 5.0, 1e-6);
  // the state itself is left as it was
  EXPECT_EQ(lagging.x(1, 2), equilibrium(1, 2) + 0.1);
}

TEST(EquilibriumError, StateAtRestLagsAPullByTheWholeDeformation) {
  // at rest every node lags, the control node itself (not yet on its target) by the whole pull
  const SpringModel model = chain(4);
  const SpringControls controls = equilibriumErrorChainPull(model, 1.0);
  const EquilibriumError e = equilibriumError(model, SpringState::atRest(model), controls);
  EXPECT_TRUE(e.converged);
  EXPECT_NEAR(e.maxDistance, 1.0, 1e-8);
  EXPECT_NEAR(e.ratioPercent, 100.0, 1e-6);
}

TEST(EquilibriumError, NoControlDisplacementGivesNoRatio) {
  const SpringModel model = chain(3);
  const SpringControls controls = equilibriumErrorChainPull(model, 0.0);
  // a free node 0.2 mm along the chain (sideways, a slack chain has no unique equilibrium)
  SpringState moved = SpringState::atRest(model);
  moved.x(0, 1) += 0.2;
  const EquilibriumError e = equilibriumError(model, moved, controls);
  EXPECT_EQ(e.controlDisplacement, 0.0);
  EXPECT_NEAR(e.maxDistance, 0.2, 1e-8);
  EXPECT_EQ(e.ratioPercent, 0.0);
}

}  // namespace
}  // namespace microsim::sim
