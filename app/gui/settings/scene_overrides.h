#pragma once
// The simulation tunables applied to a lesson's scene: when the settings ask for another
// tissue solver or iteration budget than the scene file gives, the scene definition is
// changed in memory after loading (no copy of the file is written). The attempt then runs,
// and is graded, on that definition, and its recording's metadata names the solver it was
// made with.

#include "microsim/sim/scene/scene_def.h"

#include <QJsonObject>
#include <QString>

namespace microsim::gui::settings {

struct SolverOverride {
  QString solver;      ///< "scene" or empty: keep the scene's
  int iterations = 0;  ///< 0: keep the scene's
  bool any() const { return (!solver.isEmpty() && solver != QLatin1String("scene")) || iterations > 0; }
};

/// The override the stored settings ask for.
SolverOverride solverOverrideFromSettings();

/// Applies `override` to `def`: another solver starts from its own defaults (the scene's
/// parameters belong to the scene's solver) with the scene's iteration budget, then the
/// budget is replaced when given. False, with `def` unchanged, when the solver is unknown.
bool applySolverOverride(sim::SceneDef& def, const SolverOverride& override);

/// The override as a recording's metadata states it, the shape of a scene file's "solver"
/// block: {"name": ..., "iterations": ...}; empty when it changes nothing.
QJsonObject solverOverrideJson(const sim::SceneDef& def, const SolverOverride& override);

}  // namespace microsim::gui::settings
