// microsim: the desktop app. Opens the trainee history (SQLite in the user's data
// folder unless --database says otherwise), loads the interface language, and shows
// the main window.
#include "gui/app_settings.h"
#include "gui/main_window.h"
#include "gui/render/renderer_probe.h"
#include "gui/render/surface_format.h"
#include "gui/screenshots.h"
#include "gui/start_check.h"
#include "i18n/translations.h"

#include "microsim/assessment/storage/history_database.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QSettings>

#include <cstdio>
#include <cstdlib>

int main(int argc, char** argv) {
  // the viewport's OpenGL context; ask before any context exists
  microsim::gui::useMicroscopeSurfaceFormat();

  QApplication app(argc, argv);
  // a software rasteriser (Mesa's llvmpipe, no GPU) draws without multisampling, which alone
  // costs it 2.4× in frame rate (render/renderer_probe.h); viewports are made after this
  microsim::gui::useMicroscopeSurfaceFormat(microsim::gui::microscopeSamplesFor(microsim::gui::openGlRendererName()));
  QCoreApplication::setOrganizationName(QStringLiteral("microsim"));
  QCoreApplication::setApplicationName(QStringLiteral("microsim"));
  QCoreApplication::setApplicationVersion(QStringLiteral(MICROSIM_VERSION));
  // the installed microsim.desktop: desktops match the window to its entry and icon
  QGuiApplication::setDesktopFileName(QStringLiteral("microsim"));

  microsim::i18n::installTranslations(app, microsim::i18n::languageFromSettings());

  QCommandLineParser parser;
  parser.setApplicationDescription(QApplication::translate("main", "Micro-anastomosis training simulator"));
  parser.addHelpOption();
  parser.addVersionOption();
  const QCommandLineOption screenshot(
      QStringLiteral("screenshot"),
      QApplication::translate("main", "Write a PNG of each main screen to <dir>, then quit."),
      QApplication::translate("main", "dir"));
  const QCommandLineOption database(
      QStringLiteral("database"),
      QApplication::translate("main", "Use the SQLite history file <file> instead of the default."),
      QApplication::translate("main", "file"));
  const QCommandLineOption checkStart(
      QStringLiteral("check-start"),
      QApplication::translate("main", "Start as usual, quit once the main window is drawn; exit 1 if it was not, "
                                      "or a lesson or the history could not be read."));
  parser.addOption(screenshot);
  parser.addOption(database);
  parser.addOption(checkStart);
  parser.process(app);

  if (parser.isSet(screenshot)) {
    QString error;
    const QStringList files = microsim::gui::writeScreenshots(parser.value(screenshot), &error);
    for (const QString& f : files) std::printf("%s\n", qPrintable(f));
    if (files.isEmpty()) std::fprintf(stderr, "microsim: --screenshot failed: %s\n", qPrintable(error));
    // the screens held charts and an OpenGL viewport in one process: Qt Charts' global text
    // item then crashes among the exit handlers reaching for a glyph cache whose context is
    // gone (Qt 6.4; see tests/support/gui_test_main.cpp). The files are written: leave
    // without the static destructors.
    std::fflush(nullptr);
    std::_Exit(files.isEmpty() ? 1 : 0);
  }

  QString databasePath = parser.value(database);
  if (databasePath.isEmpty())
    databasePath = QSettings().value(microsim::gui::settings::databasePath(),
                                  microsim::assessment::HistoryDatabase::defaultPath()).toString();
  microsim::assessment::HistoryDatabase history;
  const microsim::assessment::DatabaseStatus status = history.open(databasePath);
  if (!status.ok())
    std::fprintf(stderr, "microsim: %s (%s)\n",
                 qPrintable(microsim::gui::MainWindow::describe(status, databasePath)),
                 qPrintable(status.driverMessage));

  microsim::gui::MainWindow window(&history, status, databasePath);
  window.show();
  if (parser.isSet(checkStart)) return microsim::gui::checkStart(window, status, databasePath);
  return QApplication::exec();
}
