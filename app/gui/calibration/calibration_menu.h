#pragma once
// The one entry point of calibration for the main window. addCalibrationMenu adds a
// "Calibration" menu (tracker connection, replay, setup profile, the calibration wizards,
// the live view, saving the profile) and a TrackerStatusWidget on the status bar, and
// returns the CalibrationSession that owns the current tracker source and setup profile.
//
// The simulation takes its frames from sceneFrameReady: the source's tracker-frame
// frames with the profile's calibration applied (calibration::toScene):
//   connect(session, &CalibrationSession::sceneFrameReady, runner, &SimulationRunner::submitFrame);
// At start, chooseAtStart(window) lets the user pick a stored profile (it returns at once
// when there is none).
//
// The menu's sources: an OpenIGTLink tracker (the primary input), a recorded tracker stream or
// simulation recording, a 3D mouse through spacenavd and a game controller through SDL. The
// two devices produce scene-frame InputFrames (no calibration applies to them) and move the
// tools from where the scene shows them (setRateToolProviders).

#include "calibration/setup_calibration.h"
#include "tracking/frame_assembler.h"
#include "tracking/rate_tool_source.h"
#include "tracking/tracker_source.h"

#include "microsim/assessment/storage/setup_profiles.h"

#include <QObject>
#include <QPointer>

#include <memory>

class QMainWindow;
class QWidget;

namespace microsim::gui {

class TrackerStatusWidget;

class CalibrationSession : public QObject {
  Q_OBJECT

 public:
  CalibrationSession(assessment::HistoryDatabase* database, QObject* parent = nullptr);
  ~CalibrationSession() override;

  /// Uses `source` (not owned). `trackerFrame`: its frames are in the tracker frame and get
  /// the profile's calibration; false for sources that already produce scene frames.
  void setSource(tracking::TrackerSource* source, bool trackerFrame = true);
  /// Uses and owns `source` (started by the caller or by the menu's actions).
  void adoptSource(std::unique_ptr<tracking::TrackerSource> source, bool trackerFrame = true);
  tracking::TrackerSource* source() const { return source_; }
  /// Connects to an OpenIGTLink server with the profile's device mapping (reconnecting
  /// with the new mapping whenever the profile changes).
  void connectIgtl(const QString& host, quint16 port);
  /// Plays a recorded tracker stream or simulation recording at real time; false with a
  /// user-readable reason when the file cannot be played.
  bool openReplayFile(const QString& path, QString* error);
  /// Where the 3D mouse and the game controller find the tools, the view's axes and the
  /// working volume (the main window: the attempt's latest snapshot, the viewport's camera and
  /// the keyboard's working volume).
  void setRateToolProviders(tracking::RateToolSource::ToolAnchor anchor,
                            tracking::RateToolSource::ViewAxesProvider view,
                            tracking::RateToolSource::WorkingVolumeProvider volume);
  /// Whether the scene has scissors the devices' instrument swap may take up (the main window:
  /// the attempt's scene).
  void setScissorsInScene(tracking::RateToolSource::ScissorsInScene scissors) { scissorsInScene_ = std::move(scissors); }
  /// Drives the tools with a 3D mouse through spacenavd; false with a user-readable reason
  /// (and the current source kept) when the daemon does not answer.
  bool useSpacenav(QString* error);
  /// Drives the tools with the first game controller SDL finds; false with a user-readable
  /// reason (and the current source kept) when none is plugged in.
  bool useGamepad(QString* error);

  const assessment::SetupProfile& profile() const { return profile_; }
  void setProfile(const assessment::SetupProfile& profile);
  tracking::DeviceMapping mapping() const;
  calibration::SetupCalibration calibration() const;

  /// Stores the profile (asking for a name and who calibrated when it has none); true when stored.
  bool saveProfile(QWidget* parent);
  /// Shows the profile chooser when profiles exist; true when one was chosen.
  bool chooseAtStart(QWidget* parent);

  assessment::HistoryDatabase* database() const { return database_; }

 Q_SIGNALS:
  /// A frame for the simulation, in the scene frame.
  void sceneFrameReady(const microsim::sim::InputFrame& frame);
  void sourceChanged(microsim::tracking::TrackerSource* source);
  void profileChanged();

 private:
  void onFrame(const sim::InputFrame& frame);
  bool useRateSource(std::unique_ptr<tracking::RateToolSource> source, QString* error);

  assessment::HistoryDatabase* database_;
  QPointer<tracking::TrackerSource> source_;
  std::unique_ptr<tracking::TrackerSource> owned_;
  bool trackerFrame_ = true;
  QString igtlHost_;  ///< set while the owned source is an OpenIGTLink client
  quint16 igtlPort_ = 0;
  tracking::RateToolSource::ToolAnchor toolAnchor_;
  tracking::RateToolSource::ViewAxesProvider viewAxes_;
  tracking::RateToolSource::WorkingVolumeProvider workingVolume_;
  tracking::RateToolSource::ScissorsInScene scissorsInScene_;
  assessment::SetupProfile profile_;
  calibration::SetupCalibration calibration_;
};

/// Adds the Calibration menu and the tracker status to `window`; the session is a child of it.
CalibrationSession* addCalibrationMenu(QMainWindow* window, assessment::HistoryDatabase* database);

}  // namespace microsim::gui
