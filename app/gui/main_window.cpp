#include "gui/main_window.h"

#include "gui/app_settings.h"
#include "gui/calibration/calibration_menu.h"
#include "gui/pages/add_person_dialog.h"
#include "gui/pages/lesson_list_page.h"
#include "gui/pages/my_progress_page.h"
#include "gui/pages/results_page.h"
#include "gui/pages/sign_in_page.h"
#include "gui/render/renderer_probe.h"
#include "gui/review/review_page.h"
#include "gui/settings/settings_dialog.h"
#include "gui/settings/tunables.h"
#include "gui/simulation_runner.h"
#include "gui/viewport.h"
#include "gui/window_geometry.h"
#include "i18n/translations.h"
#include "tracking/manual_source.h"
#include "tracking/rate_control.h"

#include "microsim/sim/scene/recording.h"

#include <QApplication>
#include <QCloseEvent>
#include <QFileDialog>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QScrollArea>
#include <QSettings>
#include <QStackedWidget>
#include <QStatusBar>

namespace microsim::gui {

MainWindow::MainWindow(assessment::HistoryDatabase* history, const assessment::DatabaseStatus& database,
                       const QString& databasePath, QWidget* parent)
    : QMainWindow(parent), history_(history) {
  setWindowTitle(tr("microsim — micro-anastomosis trainer"));

  // the pages
  pages_ = new QStackedWidget(this);
  signIn_ = new SignInPage(history_, pages_);
  // the pages that only read the history read it off the GUI thread, from its location
  const QString historyLocation = history_ && history_->isOpen() ? history_->location() : QString();
  lessonList_ = new LessonListPage(historyLocation, pages_);
  attempt_ = new AttemptPage(history_, pages_);
  results_ = new ResultsPage(pages_);
  progress_ = new MyProgressPage(historyLocation, pages_);
  for (QWidget* page : std::initializer_list<QWidget*>{signIn_, lessonList_, attempt_, results_, progress_})
    pages_->addWidget(page);
  // a page that needs more room than the screen has scrolls instead of growing the window
  // past the screen (and having that size saved and restored)
  auto* scroll = new QScrollArea(this);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  scroll->setWidget(pages_);
  setCentralWidget(scroll);

  std::vector<lesson::LessonError> errors;
  lessons_ = lesson::loadLessons(lesson::lessonsDirectory(), &errors);

  databaseLabel_ = new QLabel(describe(database, databasePath), this);
  userLabel_ = new QLabel(this);
  statusBar()->addPermanentWidget(userLabel_);
  statusBar()->addPermanentWidget(databaseLabel_);
  if (!errors.empty())
    statusBar()->showMessage(tr("%n lesson file(s) could not be read; the first: %1 (%2)", "", static_cast<int>(errors.size()))
                                 .arg(errors.front().file, errors.front().field));

  connect(signIn_, &SignInPage::signedIn, this, [this](const assessment::Viewer& viewer, const QString& name) {
    viewer_ = viewer;
    userName_ = name;
    updatePeopleMenu();
    userLabel_->setText(viewer.role == assessment::Role::Instructor ? tr("Instructor: %1").arg(name)
                                                                     : tr("Trainee: %1").arg(name));
    if (viewer.role == assessment::Role::Instructor && history_ && history_->isOpen()) {
      showReview();
    } else {
      showLessons();
    }
  });
  connect(lessonList_, &LessonListPage::startLesson, this, &MainWindow::startLesson);
  connect(lessonList_, &LessonListPage::signOut, this, &MainWindow::signOut);
  connect(lessonList_, &LessonListPage::showProgress, this, &MainWindow::showProgress);
  connect(progress_, &MyProgressPage::back, this, &MainWindow::showLessons);
  connect(attempt_, &AttemptPage::finished, this, &MainWindow::showResults);
  connect(attempt_, &AttemptPage::abandoned, this, &MainWindow::showLessons);
  connect(results_, &ResultsPage::retry, this, [this] { startLesson(lastLesson_, lastMode_); });
  connect(results_, &ResultsPage::back, this, &MainWindow::showLessons);

  buildMenus();

  // trackers: the calibration menu, the tracker status line, and the frames of a calibrated
  // tracker into the running attempt (the keyboard and mouse drive it otherwise)
  calibration_ = addCalibrationMenu(this, history_);
  connect(calibration_, &CalibrationSession::sceneFrameReady, this, [this](const sim::InputFrame& frame) {
    if (SimulationRunner* runner = attempt_->runner()) runner->submitFrame(frame);
  });
  // the 3D mouse and the game controller move the tools from where the attempt shows them,
  // along the microscope's current axes
  calibration_->setRateToolProviders(
      [this]() -> std::optional<sim::InputFrame> {
        const SimulationRunner* runner = attempt_->runner();
        const std::shared_ptr<const sim::RenderSnapshot> shown = runner ? runner->latestSnapshot() : nullptr;
        return shown ? tracking::toolsShown(*shown) : std::nullopt;
      },
      [this] {
        const MicroscopeCamera& camera = attempt_->viewport()->camera();
        const auto axis = [](const QVector3D& v) { return Eigen::Vector3d(v.x(), v.y(), v.z()); };
        return tracking::ViewAxes{axis(camera.right()), axis(camera.up()), axis(-camera.forward())};
      },
      [this]() -> std::optional<Eigen::AlignedBox3d> {
        const SimulationRunner* runner = attempt_->runner();
        const tracking::ManualSource* keys = attempt_->manualSource();
        if (!runner || !runner->sceneDef() || !keys) return std::nullopt;
        return keys->workingVolume();
      });
  calibration_->setScissorsInScene([this] {
    const SimulationRunner* runner = attempt_->runner();
    return runner && runner->sceneDef() && runner->sceneDef()->scissors.has_value();
  });

  QSettings settings;
  if (!restoreGeometry(settings.value(settings::windowGeometry()).toByteArray())) placeFirstTime(*this);
  restoreState(settings.value(settings::windowState()).toByteArray());
  fitToScreen(*this);
}

MainWindow::~MainWindow() = default;

void MainWindow::showReview() {
  // an instructor's review is built for the viewer who signed in and dropped at sign-out
  if (review_) review_->deleteLater();
  review_ = new ReviewPage(*history_, viewer_, pages_);
  pages_->addWidget(review_);
  connect(review_, &ReviewPage::signOutRequested, this, &MainWindow::signOut);
  pages_->setCurrentWidget(review_);
}

void MainWindow::signOut() {
  viewer_ = {};
  userName_.clear();
  userLabel_->clear();
  updatePeopleMenu();
  if (review_) {
    pages_->removeWidget(review_);
    review_->deleteLater();
    review_ = nullptr;
  }
  signIn_->refresh();
  pages_->setCurrentWidget(signIn_);
}

Viewport* MainWindow::viewport() const { return attempt_->viewport(); }
QWidget* MainWindow::currentPage() const { return pages_->currentWidget(); }
QString MainWindow::databaseMessage() const { return databaseLabel_->text(); }
QString MainWindow::language() const { return i18n::languageFromSettings(); }

QString MainWindow::describe(const assessment::DatabaseStatus& status, const QString& path) {
  using assessment::DatabaseError;
  switch (status.error) {
    case DatabaseError::None:
      return tr("History: %1 (schema %2)").arg(path).arg(status.schemaVersion);
    case DatabaseError::CannotCreateFolder:
      return tr("History unavailable: cannot create the folder for %1").arg(path);
    case DatabaseError::CannotOpen:
      return tr("History unavailable: cannot open %1").arg(path);
    case DatabaseError::NotADatabase:
      return tr("History unavailable: %1 is not a microsim database or is damaged; it was left untouched").arg(path);
    case DatabaseError::Locked:
      return tr("History unavailable: %1 is locked by another program").arg(path);
    case DatabaseError::NewerSchema:
      return tr("History unavailable: %1 was written by a newer microsim").arg(path);
    case DatabaseError::MigrationFailed:
      return tr("History unavailable: updating %1 failed; it was left as it was").arg(path);
    case DatabaseError::ReadOnly:
      return tr("History unavailable: %1 is read-only; it was left untouched").arg(path);
  }
  return {};
}

void MainWindow::buildMenus() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  QAction* replay = file->addAction(tr("&Replay a recording into this attempt…"), this, &MainWindow::replayRecording);
  replay->setObjectName(QStringLiteral("replayAction"));
  QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
  quit->setShortcut(QKeySequence::Quit);
  quit->setObjectName(QStringLiteral("quitAction"));

  QMenu* settingsMenu = menuBar()->addMenu(tr("&Settings"));
  QAction* preferences = settingsMenu->addAction(tr("&Preferences…"), this, &MainWindow::openSettings);
  preferences->setShortcut(QKeySequence::Preferences);
  preferences->setObjectName(QStringLiteral("settingsAction"));

  // the microscope's named views (render/camera.h) and the key and mouse map
  QMenu* view = menuBar()->addMenu(tr("&View"));
  const auto addView = [this, view](const QString& text, const QKeySequence& key, NamedView named, const char* name) {
    QAction* action = view->addAction(text, this, [this, named] { viewport()->showView(named); });
    action->setShortcut(key);
    action->setObjectName(QString::fromLatin1(name));
  };
  addView(tr("&Microscope view (reset)"), QKeySequence(Qt::Key_Home), NamedView::Microscope, "microscopeViewAction");
  addView(tr("&Top view"), QKeySequence(Qt::Key_1), NamedView::Top, "topViewAction");
  addView(tr("&Oblique view"), QKeySequence(Qt::Key_2), NamedView::Oblique, "obliqueViewAction");
  addView(tr("&Side view"), QKeySequence(Qt::Key_3), NamedView::Side, "sideViewAction");
  view->addSeparator();
  QAction* keys = view->addAction(tr("&Keys and mouse"), this, [this] { viewport()->setHelpVisible(!viewport()->helpVisible()); });
  keys->setShortcut(QKeySequence(Qt::Key_F1));
  keys->setObjectName(QStringLiteral("keyMapAction"));
  // the microscope's shallow depth of field (render/eyepiece_pass.h), kept between sessions
  QAction* focus = view->addAction(tr("&Depth of field"));
  focus->setObjectName(QStringLiteral("depthOfFieldAction"));
  focus->setCheckable(true);
  focus->setToolTip(tr("Blur what lies above or below the focal plane, as a microscope does"));
  focus->setChecked(QSettings().value(settings::depthOfField(), depthOfFieldByDefault(openGlRendererName())).toBool());
  viewport()->setDepthOfField(focus->isChecked());
  connect(focus, &QAction::toggled, this, [this](bool on) {
    viewport()->setDepthOfField(on);
    QSettings().setValue(settings::depthOfField(), on);
  });

  // instructors add people here (trainees also create themselves at sign-in)
  peopleMenu_ = menuBar()->addMenu(tr("&People"));
  QAction* addTrainee = peopleMenu_->addAction(tr("Add a &trainee…"), this, [this] { addPerson(assessment::Role::Trainee); });
  addTrainee->setObjectName(QStringLiteral("addTraineeAction"));
  QAction* addInstructor =
      peopleMenu_->addAction(tr("Add an &instructor…"), this, [this] { addPerson(assessment::Role::Instructor); });
  addInstructor->setObjectName(QStringLiteral("addInstructorAction"));
  updatePeopleMenu();

  QMenu* help = menuBar()->addMenu(tr("&Help"));
  help->addAction(tr("&About microsim"), this, &MainWindow::showAbout);
}

void MainWindow::showLessons() {
  attempt_->stop();
  lessonList_->show(lessons_, viewer_, userName_, language());
  pages_->setCurrentWidget(lessonList_);
}

void MainWindow::showProgress(const QString& lessonId) {
  progress_->open(lessons_, viewer_, userName_, lessonId, language());
  pages_->setCurrentWidget(progress_);
}

void MainWindow::updatePeopleMenu() {
  const bool instructor = viewer_.role == assessment::Role::Instructor && viewer_.userId != 0;
  for (QAction* action : peopleMenu_->actions()) action->setEnabled(instructor);
}

void MainWindow::addPerson(assessment::Role role) {
  if (viewer_.role != assessment::Role::Instructor || !history_ || !history_->isOpen()) return;
  AddPersonDialog dialog(role, *history_, this);
  if (dialog.exec() != QDialog::Accepted) return;
  statusBar()->showMessage(role == assessment::Role::Trainee ? tr("Trainee %1 added.").arg(dialog.addedName())
                                                             : tr("Instructor %1 added.").arg(dialog.addedName()),
                           5000);
  if (review_) review_->refresh();
}

bool MainWindow::startLesson(int index, assessment::AttemptMode mode) {
  if (index < 0 || index >= static_cast<int>(lessons_.size())) return false;
  lastLesson_ = index;
  lastMode_ = mode;
  QString error;
  if (!attempt_->begin(lessons_[static_cast<std::size_t>(index)], index, mode, viewer_, language(), &error)) {
    QMessageBox::warning(this, tr("The lesson cannot start"), error);
    return false;
  }
  pages_->setCurrentWidget(attempt_);
  attempt_->startLive();
  return true;
}

void MainWindow::showResults(const AttemptResult& result) {
  const QString title = result.lessonIndex >= 0 && result.lessonIndex < static_cast<int>(lessons_.size())
                            ? lessons_[static_cast<std::size_t>(result.lessonIndex)].title.in(language())
                            : QString();
  results_->show(result, title);
  pages_->setCurrentWidget(results_);
}

void MainWindow::replayRecording() {
  if (!attempt_->isActive()) {
    statusBar()->showMessage(tr("Start a lesson first; the recording is then replayed into it."), 5000);
    return;
  }
  const QString path = QFileDialog::getOpenFileName(this, tr("Replay a recording"), {}, tr("Recordings (*.msrec)"));
  if (path.isEmpty()) return;
  sim::Recording recording;
  const sim::RecordingStatus status = sim::readRecording(path.toStdString(), recording);
  if (!status.ok() && status.error != sim::RecordingError::Truncated) {
    QMessageBox::warning(this, tr("Replay a recording"), tr("%1 is not a readable recording.").arg(path));
    return;
  }
  attempt_->replay(std::move(recording.frames));
}

void MainWindow::openSettings() {
  settings::SettingsDialog dialog(this);
  const QString languageBefore = QSettings().value(i18n::languageSettingKey()).toString();
  if (dialog.exec() != QDialog::Accepted) return;
  attempt_->applyViewSettings();
  if (QSettings().value(i18n::languageSettingKey()).toString() != languageBefore)
    statusBar()->showMessage(tr("The language changes at the next start."), 5000);
  else
    statusBar()->showMessage(tr("Settings saved; the solver applies from the next attempt."), 5000);
}

void MainWindow::showAbout() {
  QMessageBox::about(this, tr("About microsim"),
                     tr("<p><b>microsim %1</b></p><p>Practise and assessment of microvascular "
                        "anastomosis under a virtual operating microscope.</p>")
                         .arg(QStringLiteral(MICROSIM_VERSION)));
}

void MainWindow::closeEvent(QCloseEvent* event) {
  attempt_->stop();
  QSettings settings;
  settings.setValue(settings::windowGeometry(), saveGeometry());
  settings.setValue(settings::windowState(), saveState());
  event->accept();
}

}  // namespace microsim::gui
