// GoogleTest main for suites that drive real widgets: a QApplication on whatever display
// the run provides (xvfb-run in CI), and settings/data kept out of the user's folders.
#include <QApplication>
#include <QStandardPaths>

#include <gtest/gtest.h>

int main(int argc, char** argv) {
  QStandardPaths::setTestModeEnabled(true);
  QApplication app(argc, argv);
  QCoreApplication::setOrganizationName(QStringLiteral("microsim-tests"));
  QCoreApplication::setApplicationName(QStringLiteral("microsim-tests"));
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
