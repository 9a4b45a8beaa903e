#pragma once
// The part of one attempt that runs off the GUI thread, on its AttemptSession's worker
// QThread: the history connection (opened, used and closed on that thread, as QtSql wants
// of a connection) and the graded replay. Requests arrive as queued calls and run in the
// order they were posted; results leave as signals, queued to the session.
//
// The attempt in the history: begin() opens the history (which marks the attempts of
// ended sessions interrupted) and begins it; score() stores its score and recording,
// abandon() marks it abandoned. When the worker is destroyed with the attempt still in
// progress, its connection closes with it, and the next open of the history marks the
// attempt interrupted.

#include "gui/session/attempt_result.h"

#include "microsim/assessment/scoring/rubric.h"
#include "microsim/assessment/storage/history_database.h"
#include "microsim/sim/scene/scene_def.h"

#include <QObject>
#include <QString>

#include <memory>

namespace microsim::gui {

/// What grading a finished attempt needs, copied to the worker.
struct AttemptScoring {
  sim::SceneDef scene;          ///< as the attempt ran (solver settings applied)
  assessment::Rubric rubric;
  QString recordingPath;        ///< finished: the runner has closed it
  AttemptResult base;           ///< lesson, mode, vessels and recording path of the result
};

class AttemptWorker : public QObject {
  Q_OBJECT

 public:
  /// `historyLocation`: an SQLite file or PostgreSQL URL (HistoryDatabase::open); empty:
  /// nothing is stored.
  explicit AttemptWorker(QString historyLocation);
  ~AttemptWorker() override;

  /// Opens the history and begins the attempt; emits begun, or failed and begun(0).
  void begin(qint64 traineeId, const QString& lesson, assessment::AttemptMode mode);
  /// Replays the recording on the scene, scores it against the rubric and stores score and
  /// recording with the begun attempt in one transaction; emits scored.
  void score(const microsim::gui::AttemptScoring& request);
  /// Marks the begun attempt abandoned; emits abandoned (and failed first when the history
  /// refused).
  void abandon();

 Q_SIGNALS:
  void begun(qint64 attemptId);
  void scored(const microsim::gui::AttemptResult& result);
  void abandoned(bool stored);
  void failed(const microsim::gui::AttemptProblem& problem);

 private:
  QString location_;
  std::unique_ptr<assessment::HistoryDatabase> history_;  // opened by begin, on this thread
  qint64 attemptId_ = 0;
};

}  // namespace microsim::gui
