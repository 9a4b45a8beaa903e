// microsim-cli as a user runs it: the real binary through QProcess.
#include "support/cli_runner.h"

#include <gtest/gtest.h>

namespace {

using microsim::testing::CliRun;
using microsim::testing::runCli;

TEST(Cli, VersionPrintsTheProjectVersion) {
  const CliRun r = runCli({QStringLiteral("--version")});
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_EQ(r.out.trimmed().toStdString(), std::string("microsim-cli ") + MICROSIM_VERSION);
}

TEST(Cli, HelpListsEveryCommand) {
  const CliRun r = runCli({QStringLiteral("--help")});
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_TRUE(r.out.contains(QStringLiteral("Usage: microsim-cli")));
  EXPECT_TRUE(r.out.contains(QStringLiteral("bench")));
}

TEST(Cli, UnknownCommandIsAUsageError) {
  const CliRun r = runCli({QStringLiteral("frobnicate")});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(r.err.contains(QStringLiteral("unknown command 'frobnicate'")));
}

TEST(Cli, NoArgumentsIsAUsageError) {
  const CliRun r = runCli({});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(r.err.contains(QStringLiteral("Usage")));
}

TEST(Cli, BenchRejectsAnUnknownName) {
  const CliRun r = runCli({QStringLiteral("bench"), QStringLiteral("no-such-bench")});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(r.err.contains(QStringLiteral("unknown benchmark")));
}

}  // namespace
