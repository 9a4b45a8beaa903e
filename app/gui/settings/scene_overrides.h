#pragma once
// The simulation tunables applied to a lesson's scene: when the settings ask for another
// tissue solver or iteration budget than the scene file gives, a copy of the scene with
// those fields replaced is written to a private folder (tool meshes and imported surfaces
// made absolute, since they are relative to the original file). The attempt then runs and
// is graded on that copy, so its recording replays with the solver it was made with.

#include <QString>

namespace microsim::gui::settings {

struct SolverOverride {
  QString solver;      ///< "scene" or empty: keep the scene's
  int iterations = 0;  ///< 0: keep the scene's
  bool any() const { return (!solver.isEmpty() && solver != QLatin1String("scene")) || iterations > 0; }
};

/// The override the stored settings ask for.
SolverOverride solverOverrideFromSettings();

/// `scenePath` itself when `override` changes nothing; else the path of the patched copy in
/// `folder`. Empty with `error` set when the scene cannot be read or the copy not written.
QString applySolverOverride(const QString& scenePath, const SolverOverride& override,
                            const QString& folder, QString* error = nullptr);

}  // namespace microsim::gui::settings
