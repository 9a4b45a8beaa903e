#pragma once
// The replay player's controls: to start, a frame back, play/pause, a frame on, to end; a
// slider over the recording's time; the time; the speed (0.25×–4×); the event timeline under
// the slider; and, while a seek backward steps the scene again from the start, its progress.
// Keys (within the scope given to addShortcuts): Space plays or pauses, Left and Right step
// one frame, Home and End go to the start and the end.
//
// The widget only shows the player and forwards what is asked of it; the events for the
// timeline come from a ReplayEventScan of the loaded recording.

#include <QWidget>

#include <vector>

class QComboBox;
class QLabel;
class QProgressBar;
class QSlider;
class QToolButton;

namespace microsim::gui {

class ReplayEventScan;
class ReplayPlayer;
class ReplayTimeline;

class ReplayControls : public QWidget {
  Q_OBJECT

 public:
  explicit ReplayControls(ReplayPlayer* player, QWidget* parent = nullptr);
  ~ReplayControls() override;

  /// Call after the player loaded a recording: the slider's range, the position, and a scan
  /// of the recording's events for the timeline.
  void recordingLoaded();
  /// The recording is gone (another attempt shown): the scan stops, the timeline empties and
  /// the controls are disabled until the next recordingLoaded().
  void recordingUnloaded();
  /// Space, Left, Right, Home and End act on the player while the focus is in `scope`.
  void addShortcuts(QWidget* scope);

  /// The speeds offered, in the order of the speed box.
  static const std::vector<double>& speeds();

  QToolButton* playButton() const { return play_; }
  QToolButton* stepBackButton() const { return stepBack_; }
  QToolButton* stepForwardButton() const { return stepForward_; }
  QToolButton* toStartButton() const { return toStart_; }
  QToolButton* toEndButton() const { return toEnd_; }
  QSlider* slider() const { return slider_; }
  QComboBox* speedBox() const { return speed_; }
  QLabel* timeLabel() const { return time_; }
  QProgressBar* rerunProgress() const { return rerun_; }
  ReplayTimeline* timeline() const { return timeline_; }
  ReplayEventScan* eventScan() const { return scan_; }

 private:
  void showPosition(int position);
  void showTime(int position);
  void showPlaying(bool playing);
  void showRerunning(bool rerunning);

  ReplayPlayer* player_;
  ReplayEventScan* scan_ = nullptr;
  QToolButton* toStart_ = nullptr;
  QToolButton* stepBack_ = nullptr;
  QToolButton* play_ = nullptr;
  QToolButton* stepForward_ = nullptr;
  QToolButton* toEnd_ = nullptr;
  QSlider* slider_ = nullptr;
  QLabel* time_ = nullptr;
  QComboBox* speed_ = nullptr;
  QProgressBar* rerun_ = nullptr;
  ReplayTimeline* timeline_ = nullptr;
};

}  // namespace microsim::gui
