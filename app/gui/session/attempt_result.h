#pragma once
// What an attempt session hands the pages: why something failed (a reason and its data,
// never a sentence: the pages word it) and the outcome of a finished attempt.

#include "microsim/assessment/scoring/score.h"
#include "microsim/assessment/storage/history_types.h"
#include "microsim/sim/mesh/vessel.h"
#include "microsim/sim/scene/scene_events.h"

#include <QMetaType>
#include <QString>

#include <optional>
#include <vector>

namespace microsim::gui {

enum class AttemptFailure {
  RubricUnreadable,     ///< start: the lesson's rubric does not load (file, field, line)
  SceneUnreadable,      ///< start: the lesson's scene does not load (file, field, line)
  UnknownSolver,        ///< start: the solver setting names no solver (field: the name)
  HistoryUnavailable,   ///< the history could not be opened or refused the attempt: not stored
  RecordingUnreadable,  ///< finish: the attempt's recording could not be replayed for scoring (file)
  ScoreNotStored,       ///< finish: scored, but the history refused the score
  AbandonNotStored,     ///< abandon: the history did not take the abandonment
};

struct AttemptProblem {
  AttemptFailure failure = AttemptFailure::HistoryUnavailable;
  QString file;           ///< the file at fault, where there is one
  QString field;          ///< JSON field path (rubric, scene) or the unknown solver's name
  int line = 0;           ///< line of `field` in `file`
  QString driverMessage;  ///< the database's or reader's own text (data, not for display as is)
};

struct AttemptResult {
  int lessonIndex = -1;
  assessment::AttemptMode mode = assessment::AttemptMode::Learn;
  qint64 attemptId = 0;  ///< 0 when the attempt is not in the history
  bool scored = false;   ///< false: `problem` says why
  bool stored = false;   ///< the score reached the history
  std::optional<AttemptProblem> problem;
  assessment::AttemptScore score;
  std::vector<sim::PierceEvent> pierces;  ///< as the graded replay saw them
  std::vector<sim::VesselDef> vessels;    ///< the scene's vessels, for drawing the pierces
  QString recordingPath;
};

}  // namespace microsim::gui

Q_DECLARE_METATYPE(microsim::gui::AttemptProblem)
Q_DECLARE_METATYPE(microsim::gui::AttemptResult)
