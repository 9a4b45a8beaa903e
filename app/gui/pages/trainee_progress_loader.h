#pragma once
// Reads a trainee's own history in one lesson off the GUI thread, for "My progress".
//
// Each load runs through a HistoryReader (history_reader.h: a thread and a history connection
// of its own); the result comes back as a plain value through the `loaded` signal, and when
// loads overlap (the lesson changed before the last one arrived) only the newest is
// delivered. The storage layer applies the viewer's rights, so a trainee's load holds nothing
// but their own attempts and the notes on them.

#include "gui/pages/history_reader.h"

#include "microsim/assessment/storage/history_database.h"

#include <QList>
#include <QMetaType>
#include <QObject>
#include <QString>


namespace microsim::gui {

/// One lesson of one trainee's history, as the page shows it.
struct TraineeProgress {
  QString lesson;
  QList<assessment::AttemptSummary> finished;  ///< the finished attempts, oldest first
  QList<assessment::AttemptDetail> details;    ///< details[i] is finished[i]'s: metrics, feedback, notes, recording
  assessment::HistoryStatus status;            ///< not ok: the history could not be read (then both lists are empty)
};

/// The viewer's finished attempts in `lesson` with their details, through `history`'s stores.
TraineeProgress readTraineeProgress(assessment::HistoryDatabase& history, const assessment::Viewer& viewer,
                                    const QString& lesson);

class TraineeProgressLoader : public QObject {
  Q_OBJECT

 public:
  /// `historyLocation`: what HistoryDatabase::open takes (an SQLite file or a PostgreSQL URL).
  explicit TraineeProgressLoader(QString historyLocation, QObject* parent = nullptr);
  TraineeProgressLoader(const TraineeProgressLoader&) = delete;
  TraineeProgressLoader& operator=(const TraineeProgressLoader&) = delete;

  /// Starts reading `viewer`'s history in `lesson`; `loaded` follows on this object's thread.
  void load(const assessment::Viewer& viewer, const QString& lesson);

 Q_SIGNALS:
  void loaded(const microsim::gui::TraineeProgress& progress);

 private:
  HistoryReader reader_;  // waits for the loads still running when it goes
};

}  // namespace microsim::gui

Q_DECLARE_METATYPE(microsim::gui::TraineeProgress)
