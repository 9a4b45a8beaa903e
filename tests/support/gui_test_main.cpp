// GoogleTest main for suites that drive real widgets: a QApplication on whatever display
// the run provides (xvfb-run in CI), and settings/data kept out of the user's folders.
#include <QApplication>
#include <QStandardPaths>

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

int main(int argc, char** argv) {
  QStandardPaths::setTestModeEnabled(true);
  QApplication app(argc, argv);
  QCoreApplication::setOrganizationName(QStringLiteral("microsim-tests"));
  QCoreApplication::setApplicationName(QStringLiteral("microsim-tests"));
  ::testing::InitGoogleTest(&argc, argv);
  const int result = RUN_ALL_TESTS();
  // Qt Charts keeps a global text item whose destructor, run among the exit handlers after
  // a chart and an OpenGL viewport lived in one process, reaches for the OpenGL glyph cache
  // of a context already gone (Qt 6.4) and crashes after every test has passed; the results
  // are in, so leave without the static destructors
  std::fflush(nullptr);
  std::_Exit(result);
}
