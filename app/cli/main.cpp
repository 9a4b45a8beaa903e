// microsim-cli: the headless entry point. A QGuiApplication on the offscreen platform
// lets benchmarks draw their PNG plots (fonts need it) without any display.
#include "cli/cli.h"
#include "i18n/translations.h"

#include <QGuiApplication>

#include <cstdio>

int main(int argc, char** argv) {
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  QGuiApplication app(argc, argv);
  QCoreApplication::setOrganizationName(QStringLiteral("microsim"));
  QCoreApplication::setApplicationName(QStringLiteral("microsim"));
  QCoreApplication::setApplicationVersion(QStringLiteral(MICROSIM_VERSION));
  microsim::i18n::installTranslations(app, microsim::i18n::languageFromSettings());

  QTextStream out(stdout);
  QTextStream err(stderr);
  microsim::cli::Streams io{out, err};
  const int code = microsim::cli::runCli(QCoreApplication::arguments().mid(1), io);
  out.flush();
  err.flush();
  return code;
}
