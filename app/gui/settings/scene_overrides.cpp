#include "gui/settings/scene_overrides.h"

#include "gui/settings/tunables.h"

#include "microsim/sim/solve/solver.h"

namespace microsim::gui::settings {

SolverOverride solverOverrideFromSettings() {
  return {Tunables::value(solverKey()).toString(), Tunables::value(iterationsKey()).toInt()};
}

bool applySolverOverride(sim::SceneDef& def, const SolverOverride& override) {
  if (!override.solver.isEmpty() && override.solver != QLatin1String("scene")) {
    const std::string name = override.solver.toStdString();
    if (!sim::makeSolver(name)) return false;
    sim::TissueSolverDef fresh;
    fresh.name = name;
    fresh.iterations = def.solver.iterations;
    def.solver = fresh;
  }
  if (override.iterations > 0) def.solver.iterations = override.iterations;
  return true;
}

QJsonObject solverOverrideJson(const sim::SceneDef& def, const SolverOverride& override) {
  if (!override.any()) return {};
  return {{QStringLiteral("name"), QString::fromStdString(def.solver.name)},
          {QStringLiteral("iterations"), def.solver.iterations}};
}

}  // namespace microsim::gui::settings
