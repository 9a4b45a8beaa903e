#pragma once
// One attempt in detail: its summary, the per-metric table with feedback, the never-events,
// the per-pierce values (angles, bite, wall), the finished anastomosis opened with its
// errors (end_product_panel.h), the instructors' annotations (instructors may
// add one), and a 3D replay of its stored recording in its lesson's scene, with the player's
// controls and event timeline (replay_controls.h).

#include "microsim/assessment/storage/history_types.h"

#include <QWidget>

class QLabel;
class QListWidget;
class QPlainTextEdit;
class QPushButton;
class QTableWidget;

namespace microsim::gui {

class EndProductPanel;
class ReplayControls;
class ReplayPlayer;
class Viewport;

class AttemptDetailView : public QWidget {
  Q_OBJECT

 public:
  explicit AttemptDetailView(QWidget* parent = nullptr);
  ~AttemptDetailView() override;

  /// Shows `detail`; `traineeName` and `lessonTitle` head it; `scenePath` is the lesson's
  /// scene for the replay (empty: no replay); `canAnnotate` enables adding a note.
  void setAttempt(const assessment::AttemptDetail& detail, const QString& traineeName,
                  const QString& lessonTitle, const QString& scenePath, bool canAnnotate);
  void clear();
  qint64 attemptId() const { return attemptId_; }

  QTableWidget* metricsTable() const { return metrics_; }
  QTableWidget* piercesTable() const { return pierces_; }
  EndProductPanel* endProductPanel() const { return endProduct_; }
  QListWidget* annotationsList() const { return annotations_; }
  QPlainTextEdit* noteEditor() const { return note_; }
  QPushButton* addNoteButton() const { return addNote_; }
  /// The replay, created on the first "Replay" (null before).
  ReplayPlayer* replayPlayer() const { return player_; }
  /// The replay's controls and event timeline, created with the player.
  ReplayControls* replayControls() const { return controls_; }
  Viewport* replayViewport() const { return viewport_; }
  /// Starts the replay as the button does; false (with the reason shown) when it cannot.
  bool startReplay();

 Q_SIGNALS:
  /// The instructor asked to store `note` on the shown attempt.
  void annotationRequested(qint64 attemptId, const QString& note);

 private:
  void fillMetrics(const assessment::AttemptDetail& detail);
  void fillPierces(const assessment::AttemptDetail& detail);
  void fillAnnotations(const assessment::AttemptDetail& detail);

  qint64 attemptId_ = 0;
  QByteArray recording_;
  QString scenePath_;
  QLabel* heading_ = nullptr;
  QLabel* neverEvents_ = nullptr;
  QTableWidget* metrics_ = nullptr;
  QTableWidget* pierces_ = nullptr;
  EndProductPanel* endProduct_ = nullptr;
  QListWidget* annotations_ = nullptr;
  QPlainTextEdit* note_ = nullptr;
  QPushButton* addNote_ = nullptr;
  QPushButton* replay_ = nullptr;
  ReplayControls* controls_ = nullptr;
  QLabel* replayStatus_ = nullptr;
  QWidget* replayArea_ = nullptr;
  ReplayPlayer* player_ = nullptr;
  Viewport* viewport_ = nullptr;
};

}  // namespace microsim::gui
