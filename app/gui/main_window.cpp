#include "gui/main_window.h"

#include "gui/app_settings.h"
#include "i18n/translations.h"
#include "gui/viewport.h"

#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>

namespace microsim::gui {

MainWindow::MainWindow(const assessment::DatabaseStatus& database, const QString& databasePath,
                       QWidget* parent)
    : QMainWindow(parent) {
  setWindowTitle(tr("microsim — micro-anastomosis trainer"));
  viewport_ = new Viewport(this);
  setCentralWidget(viewport_);
  buildMenus();

  databaseLabel_ = new QLabel(describe(database, databasePath), this);
  statusBar()->addPermanentWidget(databaseLabel_);
  statusBar()->showMessage(tr("Drag to orbit the microscope, wheel to zoom."));

  QSettings settings;
  restoreGeometry(settings.value(settings::windowGeometry()).toByteArray());
  restoreState(settings.value(settings::windowState()).toByteArray());
}

QString MainWindow::databaseMessage() const { return databaseLabel_->text(); }

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
  }
  return {};
}

void MainWindow::buildMenus() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
  quit->setShortcut(QKeySequence::Quit);
  quit->setObjectName(QStringLiteral("quitAction"));

  QMenu* settingsMenu = menuBar()->addMenu(tr("&Settings"));
  QMenu* language = settingsMenu->addMenu(tr("&Language"));
  auto* group = new QActionGroup(this);
  const QString current = QSettings().value(i18n::languageSettingKey()).toString();
  const QStringList names = {tr("System default"), tr("English"), tr("German"), tr("Spanish")};
  const QStringList codes = {QString(), QStringLiteral("en"), QStringLiteral("de"), QStringLiteral("es")};
  for (qsizetype i = 0; i < codes.size(); ++i) {
    QAction* action = language->addAction(names[i]);
    action->setCheckable(true);
    action->setChecked(codes[i] == current);
    group->addAction(action);
    const QString code = codes[i];
    connect(action, &QAction::triggered, this, [this, code] { chooseLanguage(code); });
  }

  QMenu* help = menuBar()->addMenu(tr("&Help"));
  help->addAction(tr("&About microsim"), this, &MainWindow::showAbout);
}

void MainWindow::chooseLanguage(const QString& language) {
  QSettings().setValue(i18n::languageSettingKey(), language);
  statusBar()->showMessage(tr("The language changes at the next start."), 5000);
}

void MainWindow::showAbout() {
  QMessageBox::about(this, tr("About microsim"),
                     tr("<p><b>microsim %1</b></p><p>Practise and assessment of microvascular "
                        "anastomosis under a virtual operating microscope.</p>")
                         .arg(QStringLiteral(MICROSIM_VERSION)));
}

void MainWindow::closeEvent(QCloseEvent* event) {
  QSettings settings;
  settings.setValue(settings::windowGeometry(), saveGeometry());
  settings.setValue(settings::windowState(), saveState());
  event->accept();
}

}  // namespace microsim::gui
