// GoogleTest main for suites that need a QCoreApplication (QtSql, event loops).
#include <QCoreApplication>

#include <gtest/gtest.h>

int main(int argc, char** argv) {
  QCoreApplication app(argc, argv);
  QCoreApplication::setOrganizationName(QStringLiteral("microsim-tests"));
  QCoreApplication::setApplicationName(QStringLiteral("microsim-tests"));
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
