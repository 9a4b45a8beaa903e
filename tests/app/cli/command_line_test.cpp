// Every subcommand's command line has one shape (cli/command_line.h): --help, a stray word and
// an unknown option behave alike in each, tried on the real binary for every command that
// `microsim-cli --help` lists; and the shape itself, in process.
#include "cli/command_line.h"
#include "cli/commands.h"
#include "support/cli_runner.h"

#include <QTextStream>

#include <gtest/gtest.h>

#include <map>

namespace {

using microsim::cli::CommandLine;
using microsim::cli::kExitFailure;
using microsim::cli::kExitOk;
using microsim::cli::kExitUsage;
using microsim::cli::Streams;
using microsim::testing::CliRun;
using microsim::testing::runCli;

// how many words each command takes after its name (db: an action and its file or name)
const std::map<QString, int> kWordsTaken = {
    {QStringLiteral("solve"), 0}, {QStringLiteral("export"), 0}, {QStringLiteral("bench"), 1},
    {QStringLiteral("run"), 0},   {QStringLiteral("track"), 0},  {QStringLiteral("calibrate"), 1},
    {QStringLiteral("score"), 0}, {QStringLiteral("db"), 2},
};

TEST(CommandLine, EveryCommandIsInTheTable) {
  for (const microsim::cli::Command& c : microsim::cli::commands())
    EXPECT_TRUE(kWordsTaken.contains(c.name)) << c.name.toStdString();
  EXPECT_EQ(kWordsTaken.size(), microsim::cli::commands().size());
}

TEST(CommandLine, EveryCommandsHelpShowsItsUsageAndOptions) {
  for (const microsim::cli::Command& c : microsim::cli::commands()) {
    SCOPED_TRACE(c.name.toStdString());
    for (const QString& flag : {QStringLiteral("--help"), QStringLiteral("-h")}) {
      const CliRun r = runCli({c.name, flag});
      EXPECT_EQ(r.exitCode, 0) << r.err.toStdString();
      EXPECT_TRUE(
          r.out.startsWith(QStringLiteral("Usage: microsim-cli ") + c.name + QLatin1Char(' ')))
          << r.out.toStdString();
      EXPECT_TRUE(r.out.contains(QStringLiteral("Options:"))) << r.out.toStdString();
      EXPECT_TRUE(r.out.contains(QStringLiteral("-h, --help"))) << r.out.toStdString();
      EXPECT_FALSE(r.err.contains(QStringLiteral("microsim-cli"))) << r.err.toStdString();
    }
  }
}

TEST(CommandLine, EveryCommandRefusesAStrayWordByName) {
  for (const microsim::cli::Command& c : microsim::cli::commands()) {
    SCOPED_TRACE(c.name.toStdString());
    const int taken = kWordsTaken.at(c.name);
    QStringList args{c.name};
    for (int w = 0; w <= taken; ++w) args << QStringLiteral("word%1").arg(w);
    const CliRun r = runCli(args);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_TRUE(r.out.isEmpty()) << r.out.toStdString();
    EXPECT_TRUE(r.err.contains(
        QStringLiteral("microsim-cli %1: unexpected argument 'word%2'\n").arg(c.name).arg(taken)))
        << r.err.toStdString();
  }
}

TEST(CommandLine, EveryCommandRefusesAnUnknownOptionByName) {
  for (const microsim::cli::Command& c : microsim::cli::commands()) {
    SCOPED_TRACE(c.name.toStdString());
    for (const QString& option :
         {QStringLiteral("--no-such-option"), QStringLiteral("--no-such-option=3")}) {
      const CliRun r = runCli({c.name, option});
      EXPECT_EQ(r.exitCode, 2);
      EXPECT_TRUE(r.out.isEmpty()) << r.out.toStdString();
      EXPECT_TRUE(r.err.contains(
          QStringLiteral("microsim-cli %1: Unknown option 'no-such-option'").arg(c.name)))
          << r.err.toStdString();
    }
    // every command writes --json FILE: given without its value
    const CliRun missing = runCli({c.name, QStringLiteral("--json")});
    EXPECT_EQ(missing.exitCode, 2);
    EXPECT_TRUE(missing.err.contains(
        QStringLiteral("microsim-cli %1: Missing value after '--json'").arg(c.name)))
        << missing.err.toStdString();
  }
}

// the shape in process: what each report gives back and prints
struct CapturedStreams {
  QString outText, errText;
  QTextStream out{&outText}, err{&errText};
  Streams io{out, err};
};

TEST(CommandLine, ReportsGoThroughOnePrefixWithTheirExitCodes) {
  CapturedStreams s;
  CommandLine line(QStringLiteral("frob"), QStringLiteral("Usage: microsim-cli frob [--json FILE]"),
                   s.io);
  const QCommandLineOption json(QStringLiteral("json"), QStringLiteral("Write JSON to <file>."),
                                QStringLiteral("file"));
  line.addOptions({json});
  EXPECT_EQ(line.parse({QStringLiteral("--json"), QStringLiteral("x.json")}), std::nullopt);
  EXPECT_EQ(line.value(json), QStringLiteral("x.json"));
  EXPECT_EQ(line.usageError(QStringLiteral("wrong")), kExitUsage);
  EXPECT_EQ(line.failure(QStringLiteral("failed")), kExitFailure);
  line.warning(QStringLiteral("careful"));
  s.err.flush();
  EXPECT_EQ(s.errText, QStringLiteral("microsim-cli frob: wrong\nmicrosim-cli frob: failed\n"
                                      "microsim-cli frob: warning: careful\n"));
  s.out.flush();
  EXPECT_TRUE(s.outText.isEmpty());
}

TEST(CommandLine, HelpPrintsTheUsageOptionsWordsAndDetails) {
  CapturedStreams s;
  CommandLine line(QStringLiteral("frob"), QStringLiteral("Usage: microsim-cli frob NAME"), s.io);
  line.addWord(QStringLiteral("name"), QStringLiteral("What to frob."));
  line.setHelpDetails(QStringLiteral("Frobbable: a, b\n"));
  EXPECT_EQ(line.parse({QStringLiteral("a"), QStringLiteral("--help")}), kExitOk);
  s.out.flush();
  EXPECT_TRUE(s.outText.startsWith(QStringLiteral("Usage: microsim-cli frob NAME\n\nOptions:\n")))
      << s.outText.toStdString();
  EXPECT_TRUE(s.outText.contains(QStringLiteral("What to frob."))) << s.outText.toStdString();
  EXPECT_TRUE(s.outText.endsWith(QStringLiteral("\nFrobbable: a, b\n"))) << s.outText.toStdString();

  CapturedStreams one;
  CommandLine oneWord(QStringLiteral("frob"), QStringLiteral("Usage: microsim-cli frob NAME"),
                      one.io);
  oneWord.addWord(QStringLiteral("name"), QStringLiteral("What to frob."));
  EXPECT_EQ(oneWord.parse({QStringLiteral("a")}), std::nullopt);
  EXPECT_EQ(oneWord.words(), QStringList{QStringLiteral("a")});

  CapturedStreams two;
  CommandLine twoWords(QStringLiteral("frob"), QStringLiteral("Usage: microsim-cli frob NAME"),
                       two.io);
  twoWords.addWord(QStringLiteral("name"), QStringLiteral("What to frob."));
  EXPECT_EQ(twoWords.parse({QStringLiteral("a"), QStringLiteral("b")}), kExitUsage);
  two.err.flush();
  EXPECT_EQ(two.errText, QStringLiteral("microsim-cli frob: unexpected argument 'b'\n"));
}

}  // namespace
