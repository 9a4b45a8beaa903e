// packaging/microsim.1.in, the installed manual of the desktop program, against what
// `microsim --help` says.
#include "support/man_page.h"

#include <QProcess>

#include <gtest/gtest.h>

namespace microsim::gui {
namespace {

TEST(AppManPage, HasEveryOptionOfTheProgram) {
  const QString manPage = testing::manPageSource(QStringLiteral("microsim.1.in"));
  ASSERT_FALSE(manPage.isEmpty());
  QProcess app;
  app.start(QStringLiteral(MICROSIM_GUI_PATH), {QStringLiteral("--help")});
  ASSERT_TRUE(app.waitForFinished(60000));
  ASSERT_EQ(app.exitCode(), 0);
  const QString help = QString::fromUtf8(app.readAllStandardOutput());
  ASSERT_TRUE(help.contains(QStringLiteral("--check-start"))) << help.toStdString();
  EXPECT_EQ(testing::optionsMissingFromManPage(help, manPage), QStringList());
}

}  // namespace
}  // namespace microsim::gui
