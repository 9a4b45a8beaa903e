#include "gui/calibration/calibration_menu.h"

#include "gui/calibration/closure_dialog.h"
#include "gui/calibration/latency_dialog.h"
#include "gui/calibration/live_tool_view.h"
#include "gui/calibration/motion_scaling_dialog.h"
#include "gui/calibration/pivot_wizard.h"
#include "gui/calibration/profile_chooser_dialog.h"
#include "gui/calibration/profile_conversion.h"
#include "gui/calibration/registration_wizard.h"
#include "gui/calibration/tracker_status_widget.h"
#include "tracking/gamepad_source.h"
#include "tracking/igtl_client.h"
#include "tracking/replay_source.h"
#include "tracking/spacenav_source.h"

#include <QFileDialog>
#include <QInputDialog>
#include <QMainWindow>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>

namespace microsim::gui {

namespace {

const QString kProfileKey = QStringLiteral("calibration/profile");

}  // namespace

CalibrationSession::CalibrationSession(assessment::HistoryDatabase* database, QObject* parent)
    : QObject(parent), database_(database) {
  profile_.calibratedAt = QDateTime::currentDateTimeUtc();
  calibration_ = setupCalibration(profile_);
}

CalibrationSession::~CalibrationSession() {
  if (owned_) owned_->stop();
}

void CalibrationSession::setSource(tracking::TrackerSource* source, bool trackerFrame) {
  if (source_ != nullptr) disconnect(source_, nullptr, this, nullptr);
  if (owned_ && owned_.get() != source) {
    owned_->stop();
    owned_.reset();
    igtlHost_.clear();
  }
  source_ = source;
  trackerFrame_ = trackerFrame;
  if (source_ != nullptr) connect(source_, &tracking::TrackerSource::frameReady, this, &CalibrationSession::onFrame);
  Q_EMIT sourceChanged(source_);
}

void CalibrationSession::adoptSource(std::unique_ptr<tracking::TrackerSource> source, bool trackerFrame) {
  tracking::TrackerSource* raw = source.get();
  setSource(raw, trackerFrame);
  owned_ = std::move(source);
}

void CalibrationSession::connectIgtl(const QString& host, quint16 port) {
  tracking::IgtlClientConfig config;
  config.host = host;
  config.port = port;
  config.mapping = mapping();
  adoptSource(std::make_unique<tracking::IgtlClient>(config));
  igtlHost_ = host;
  igtlPort_ = port;
  owned_->start();
}

bool CalibrationSession::openReplayFile(const QString& path, QString* error) {
  tracking::ReplayConfig config;
  config.mapping = mapping();
  tracking::ReplayFileStatus status;
  std::unique_ptr<tracking::ReplaySource> replay = tracking::openReplay(path, config, status);
  if (!replay) {
    *error = status.error == tracking::ReplayFileError::CannotOpen ? tr("Cannot read %1.").arg(path)
             : status.error == tracking::ReplayFileError::NotAReplay
                 ? tr("%1 is neither a recording nor a tracker stream.").arg(path)
                 : tr("%1 is damaged.").arg(path);
    return false;
  }
  // a simulation recording is already in the scene frame
  const bool trackerFrame = !replay->playsRecording();
  adoptSource(std::move(replay), trackerFrame);
  owned_->start();
  return true;
}

void CalibrationSession::setRateToolProviders(tracking::RateToolSource::ToolAnchor anchor,
                                              tracking::RateToolSource::ViewAxesProvider view,
                                              tracking::RateToolSource::WorkingVolumeProvider volume) {
  toolAnchor_ = std::move(anchor);
  viewAxes_ = std::move(view);
  workingVolume_ = std::move(volume);
}

bool CalibrationSession::useSpacenav(QString* error) {
  // libspnav holds one connection per process: the one in use stays
  if (auto* current = qobject_cast<tracking::SpacenavSource*>(source_.data()); current && current->status().connected)
    return true;
  return useRateSource(std::make_unique<tracking::SpacenavSource>(), error);
}

bool CalibrationSession::useGamepad(QString* error) {
  return useRateSource(std::make_unique<tracking::GamepadSource>(), error);
}

bool CalibrationSession::useRateSource(std::unique_ptr<tracking::RateToolSource> source, QString* error) {
  source->setToolAnchor(toolAnchor_);
  source->setViewAxesProvider(viewAxes_);
  source->setWorkingVolumeProvider(workingVolume_);
  source->setScissorsInScene(scissorsInScene_);
  source->start();
  if (!source->status().connected) {
    *error = source->status().lastError;
    return false;
  }
  // the devices move the tools in the scene frame: no calibration applies
  adoptSource(std::move(source), false);
  return true;
}

void CalibrationSession::setProfile(const assessment::SetupProfile& profile) {
  profile_ = profile;
  calibration_ = setupCalibration(profile_);
  if (profile_.id != 0) QSettings().setValue(kProfileKey, profile_.id);
  // an OpenIGTLink client maps devices at connection: reconnect with the new mapping
  if (!igtlHost_.isEmpty()) connectIgtl(QString(igtlHost_), igtlPort_);
  Q_EMIT profileChanged();
}

tracking::DeviceMapping CalibrationSession::mapping() const { return deviceMapping(profile_); }

calibration::SetupCalibration CalibrationSession::calibration() const { return calibration_; }

void CalibrationSession::onFrame(const sim::InputFrame& frame) {
  Q_EMIT sceneFrameReady(trackerFrame_ ? calibration::toScene(frame, calibration_) : frame);
}

bool CalibrationSession::saveProfile(QWidget* parent) {
  if (database_ == nullptr || !database_->isOpen()) {
    QMessageBox::warning(parent, tr("Save setup profile"), tr("The database is not open."));
    return false;
  }
  bool ok = false;
  const QString name = QInputDialog::getText(parent, tr("Save setup profile"), tr("Profile name:"), QLineEdit::Normal,
                                             profile_.name, &ok)
                           .trimmed();
  if (!ok || name.isEmpty()) return false;
  const QString by = QInputDialog::getText(parent, tr("Save setup profile"), tr("Calibrated by:"), QLineEdit::Normal,
                                           profile_.calibratedBy, &ok);
  if (!ok) return false;
  assessment::SetupProfile p = profile_;
  p.name = name;
  p.calibratedBy = by.trimmed();
  p.calibratedAt = QDateTime::currentDateTimeUtc();
  assessment::SetupProfileStore store(*database_);
  const std::optional<qint64> id = store.save(p);
  if (!id) {
    QMessageBox::warning(parent, tr("Save setup profile"), tr("The profile could not be stored: %1").arg(store.lastError()));
    return false;
  }
  p.id = *id;
  setProfile(p);
  return true;
}

bool CalibrationSession::chooseAtStart(QWidget* parent) {
  if (database_ == nullptr || !database_->isOpen()) return false;
  assessment::SetupProfileStore store(*database_);
  if (store.list().isEmpty()) return false;
  ProfileChooserDialog dialog(database_, parent);
  dialog.reload(QSettings().value(kProfileKey).toLongLong());
  if (dialog.exec() != QDialog::Accepted || !dialog.selectedProfile()) return false;
  setProfile(*dialog.selectedProfile());
  return true;
}

CalibrationSession* addCalibrationMenu(QMainWindow* window, assessment::HistoryDatabase* database) {
  auto* session = new CalibrationSession(database, window);
  auto* status = new TrackerStatusWidget(window);
  window->statusBar()->addPermanentWidget(status);
  QObject::connect(session, &CalibrationSession::sourceChanged, status, &TrackerStatusWidget::setSource);

  QMenu* menu = window->menuBar()->addMenu(CalibrationSession::tr("&Calibration"));
  const auto needSource = [session, window] {
    if (session->source() != nullptr) return true;
    QMessageBox::information(window, CalibrationSession::tr("Calibration"),
                             CalibrationSession::tr("Connect a tracker or open a tracker recording first."));
    return false;
  };

  // sources
  menu->addAction(CalibrationSession::tr("Connect to OpenIGTLink…"), window, [session, window] {
    bool ok = false;
    const QString text = QInputDialog::getText(window, CalibrationSession::tr("Connect to OpenIGTLink"),
                                               CalibrationSession::tr("Server (host:port):"), QLineEdit::Normal,
                                               QStringLiteral("127.0.0.1:18944"), &ok);
    QString host;
    quint16 port = 0;
    if (!ok) return;
    if (!tracking::parseHostPort(text, host, port)) {
      QMessageBox::warning(window, CalibrationSession::tr("Connect to OpenIGTLink"),
                           CalibrationSession::tr("Give the server as host:port."));
      return;
    }
    session->connectIgtl(host, port);
  });
  menu->addAction(CalibrationSession::tr("Play a tracker recording…"), window, [session, window] {
    const QString path = QFileDialog::getOpenFileName(window, CalibrationSession::tr("Play a tracker recording"), {},
                                                      CalibrationSession::tr("Recordings (*.json *.msrec)"));
    QString error;
    if (!path.isEmpty() && !session->openReplayFile(path, &error))
      QMessageBox::warning(window, CalibrationSession::tr("Play a tracker recording"), error);
  });
  QAction* spacenav = menu->addAction(CalibrationSession::tr("Use a 3D mouse (spacenavd)"), window, [session, window] {
    QString error;
    if (!session->useSpacenav(&error)) {
      QMessageBox::warning(window, CalibrationSession::tr("3D mouse"), error);
      return;
    }
    window->statusBar()->showMessage(
        CalibrationSession::tr("3D mouse connected: push or turn the cap to move the active forceps; "
                               "the left button closes the jaws, the right one switches the hand."),
        8000);
  });
  spacenav->setObjectName(QStringLiteral("useSpacenavAction"));
  QAction* gamepad = menu->addAction(CalibrationSession::tr("Use a game controller"), window, [session, window] {
    QString error;
    if (!session->useGamepad(&error)) {
      QMessageBox::warning(window, CalibrationSession::tr("Game controller"), error);
      return;
    }
    const auto* pad = qobject_cast<tracking::GamepadSource*>(session->source());
    window->statusBar()->showMessage(
        CalibrationSession::tr("%1 connected: sticks move the active forceps, the triggers close the jaws, "
                               "the shoulder buttons choose the hand.")
            .arg(pad != nullptr ? pad->deviceName() : CalibrationSession::tr("Game controller")),
        8000);
  });
  gamepad->setObjectName(QStringLiteral("useGamepadAction"));
  menu->addSeparator();

  // the profile
  menu->addAction(CalibrationSession::tr("Setup profile…"), window, [session, window, database] {
    ProfileChooserDialog dialog(database, window);
    dialog.reload(session->profile().id);
    if (dialog.exec() == QDialog::Accepted && dialog.selectedProfile()) session->setProfile(*dialog.selectedProfile());
  });
  menu->addAction(CalibrationSession::tr("Save setup profile…"), window, [session, window] { session->saveProfile(window); });
  menu->addSeparator();

  // the calibrations, each writing into the current profile
  menu->addAction(CalibrationSession::tr("Pivot calibration…"), window, [session, window, needSource] {
    if (!needSource()) return;
    PivotWizard wizard(session->source(), {}, window);
    if (wizard.exec() != QDialog::Accepted) return;
    assessment::SetupProfile p = session->profile();
    assessment::ProfileHand& hand = p.hands[static_cast<int>(wizard.hand())];
    hand.device = wizard.device();
    hand.tipOffset = wizard.result().tipOffset;
    hand.pivotRmsMm = wizard.result().rmsError;
    session->setProfile(p);
  });
  menu->addAction(CalibrationSession::tr("Registration…"), window, [session, window, needSource] {
    if (!needSource()) return;
    const assessment::ProfileHand& pointer = session->profile().hands[0];
    RegistrationWizard wizard(session->source(), pointer.device, pointer.tipOffset, window);
    if (wizard.exec() != QDialog::Accepted) return;
    assessment::SetupProfile p = session->profile();
    p.trackerToScene = wizard.result().transform;
    p.freMm = wizard.result().freRms;
    p.treMm = wizard.result().checkCount > 0 ? std::optional<double>(wizard.result().treRms) : std::nullopt;
    session->setProfile(p);
  });
  menu->addAction(CalibrationSession::tr("Forceps closure…"), window, [session, window, needSource] {
    if (!needSource()) return;
    bool ok = false;
    const QStringList hands{CalibrationSession::tr("Left hand"), CalibrationSession::tr("Right hand")};
    const QString hand = QInputDialog::getItem(window, CalibrationSession::tr("Forceps closure"),
                                               CalibrationSession::tr("Hand:"), hands, 0, false, &ok);
    if (!ok) return;
    const int h = static_cast<int>(hands.indexOf(hand));
    ClosureDialog dialog(session->source(), 1e-6, window);
    if (!session->profile().hands[h].closureChannel.isEmpty()) dialog.setChannel(session->profile().hands[h].closureChannel);
    if (dialog.exec() != QDialog::Accepted) return;
    assessment::SetupProfile p = session->profile();
    p.hands[h].closureChannel = dialog.channel();
    p.hands[h].closureOpen = dialog.range().open();
    p.hands[h].closureClosed = dialog.range().closed();
    session->setProfile(p);
  });
  menu->addAction(CalibrationSession::tr("Motion scaling…"), window, [session, window] {
    MotionScalingDialog dialog(session->profile().handPerScene, session->profile().scalingAnchor, window);
    if (dialog.exec() != QDialog::Accepted) return;
    assessment::SetupProfile p = session->profile();
    p.handPerScene = dialog.handPerScene();
    p.scalingAnchor = dialog.anchor();
    session->setProfile(p);
  });
  menu->addAction(CalibrationSession::tr("Latency…"), window, [session, window, needSource] {
    if (!needSource()) return;
    LatencyDialog dialog(session->source(), session->source(), window);
    dialog.setDevices(session->profile().hands[0].device, session->profile().hands[1].device);
    if (dialog.exec() != QDialog::Accepted) return;
    assessment::SetupProfile p = session->profile();
    p.latencyS = dialog.result().latency;
    session->setProfile(p);
  });
  menu->addSeparator();

  // the live view, in its own window
  menu->addAction(CalibrationSession::tr("Live view of the tools"), window, [session, window] {
    auto* view = new LiveToolView(window);
    view->setWindowFlag(Qt::Window);
    view->setAttribute(Qt::WA_DeleteOnClose);
    view->setWindowTitle(CalibrationSession::tr("Calibrated tools"));
    view->setSource(session->source());
    view->setCalibration(session->mapping(), session->calibration());
    QObject::connect(session, &CalibrationSession::sourceChanged, view, &LiveToolView::setSource);
    QObject::connect(session, &CalibrationSession::profileChanged, view,
                     [session, view] { view->setCalibration(session->mapping(), session->calibration()); });
    view->show();
  });
  return session;
}

}  // namespace microsim::gui
