#pragma once
// The part of one attempt that runs off the GUI thread, on its AttemptSession's worker
// QThread: the history connection (opened, used and closed on that thread, as QtSql wants
// of a connection) and the graded replay. Requests arrive as the signals of the session's
// AttemptRequests, connected queued to the slots below, so they run on the worker's thread
// in the order they were sent; results leave as signals, queued to the session.
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

/// What the session asks of its worker; each signal is connected queued to the worker's slot
/// of the same name.
class AttemptRequests : public QObject {
  Q_OBJECT

 Q_SIGNALS:
  void begin();
  void score(const microsim::gui::AttemptScoring& request);
  void abandon();
  void close();
};

class AttemptWorker : public QObject {
  Q_OBJECT

 public:
  /// The attempt of `traineeId` at `lesson` in `mode`; `historyLocation`: an SQLite file or
  /// PostgreSQL URL (HistoryDatabase::open); empty: nothing is stored.
  AttemptWorker(QString historyLocation, qint64 traineeId, QString lesson, assessment::AttemptMode mode);
  ~AttemptWorker() override;

 public Q_SLOTS:
  /// Opens the history and begins the attempt; emits begun, or failed and begun(0).
  void begin();
  /// Replays the recording on the scene, scores it against the rubric and stores score and
  /// recording with the begun attempt in one transaction; emits scored.
  void score(const microsim::gui::AttemptScoring& request);
  /// Marks the begun attempt abandoned; emits abandoned (and failed first when the history
  /// refused).
  void abandon();
  /// Ends the worker's thread once this call is reached: after every request sent before it.
  void close();

 Q_SIGNALS:
  void begun(qint64 attemptId);
  void scored(const microsim::gui::AttemptResult& result);
  void abandoned(bool stored);
  void failed(const microsim::gui::AttemptProblem& problem);

 private:
  QString location_;
  qint64 traineeId_;
  QString lesson_;
  assessment::AttemptMode mode_;
  std::unique_ptr<assessment::HistoryDatabase> history_;  // opened by begin, on this thread
  qint64 attemptId_ = 0;
};

}  // namespace microsim::gui

Q_DECLARE_METATYPE(microsim::gui::AttemptScoring)
