// GoogleTest main for suites that drive real widgets: a QApplication on whatever display
// the run provides (xvfb-run in CI), and settings/data kept out of the user's folders (the
// settings in a temporary folder of the process's own).
#include <QApplication>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

int main(int argc, char** argv) {
  QStandardPaths::setTestModeEnabled(true);
  QApplication app(argc, argv);
  QCoreApplication::setOrganizationName(QStringLiteral("microsim-tests"));
  QCoreApplication::setApplicationName(QStringLiteral("microsim-tests"));
  // settings of this process's own: CTest runs each test as a process, two at a time, and a
  // test that clears or sets a tunable must not change one that another test is reading
  QTemporaryDir settingsDir;
  QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, settingsDir.path());
  QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settingsDir.path());
  ::testing::InitGoogleTest(&argc, argv);
  const int result = RUN_ALL_TESTS();
  settingsDir.remove();
  // Qt Charts keeps a global text item whose destructor, run among the exit handlers after
  // a chart and an OpenGL viewport lived in one process, reaches for the OpenGL glyph cache
  // of a context already gone (Qt 6.4) and crashes after every test has passed; the results
  // are in, so leave without the static destructors
  std::fflush(nullptr);
  std::_Exit(result);
}
