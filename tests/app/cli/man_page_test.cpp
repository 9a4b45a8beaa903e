// packaging/microsim-cli.1.in, the installed manual, against what microsim-cli itself says.
#include "support/cli_runner.h"
#include "support/man_page.h"

#include <gtest/gtest.h>

namespace microsim::cli {
namespace {

using testing::CliRun;
using testing::manPageSource;
using testing::optionsMissingFromManPage;
using testing::roffWord;
using testing::runCli;

// the first word of each indented line after `heading` in `help`, up to the next blank line
QStringList manPageTestListedNames(const QString& help, const QString& heading) {
  QStringList names;
  const QStringList lines = help.split(QLatin1Char('\n'));
  const auto start = lines.indexOf(heading);
  for (qsizetype i = start + 1; start >= 0 && i < lines.size() && !lines[i].trimmed().isEmpty(); ++i)
    names << lines[i].trimmed().section(QLatin1Char(' '), 0, 0);
  return names;
}

TEST(CliManPage, HasASectionWithEveryOptionOfEveryCommand) {
  const QString manPage = manPageSource(QStringLiteral("microsim-cli.1.in"));
  ASSERT_FALSE(manPage.isEmpty());
  const CliRun top = runCli({QStringLiteral("--help")});
  ASSERT_EQ(top.exitCode, 0);
  const QStringList commands = manPageTestListedNames(top.out, QStringLiteral("Commands:"));
  ASSERT_GE(commands.size(), 8) << top.out.toStdString();
  EXPECT_TRUE(optionsMissingFromManPage(top.out, manPage).isEmpty());

  for (const QString& command : commands) {
    SCOPED_TRACE(command.toStdString());
    EXPECT_TRUE(manPage.contains(QStringLiteral("\n.SS ") + command + QLatin1Char('\n')));
    const CliRun help = runCli({command, QStringLiteral("--help")});
    ASSERT_EQ(help.exitCode, 0) << help.err.toStdString();
    EXPECT_EQ(optionsMissingFromManPage(help.out, manPage), QStringList());
  }
}

TEST(CliManPage, NamesEveryBenchmark) {
  const QString manPage = manPageSource(QStringLiteral("microsim-cli.1.in"));
  const CliRun list = runCli({QStringLiteral("bench"), QStringLiteral("--list")});
  ASSERT_EQ(list.exitCode, 0);
  const QStringList benchmarks = manPageTestListedNames(list.out, QStringLiteral("Benchmarks:"));
  ASSERT_GE(benchmarks.size(), 7) << list.out.toStdString();
  for (const QString& name : benchmarks)
    EXPECT_TRUE(manPage.contains(QStringLiteral(".B ") + roffWord(name) + QLatin1Char('\n'))) << name.toStdString();
}

TEST(CliManPage, AnOptionTheManPageLacksIsFound) {
  // the check itself can fail: an option absent from the page is reported, once
  const QString page = QStringLiteral(".TP\n.BI \\-\\-scene \" file\"\n");
  EXPECT_EQ(optionsMissingFromManPage(QStringLiteral("--scene <file> --frames <n> --frames"), page),
            QStringList{QStringLiteral("--frames")});
}

}  // namespace
}  // namespace microsim::cli
