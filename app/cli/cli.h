#pragma once
// microsim-cli: every capability reachable without a display. Each subcommand lives in
// its own file and is listed once in cli.cpp; runCli is the whole program, callable
// in-process by tests.
//
// Exit codes: 0 success, 1 the command ran and failed (bad input file, solver error),
// 2 the command line itself was wrong.

#include <QCoreApplication>
#include <QString>
#include <QStringList>
#include <QTextStream>

#include <vector>

namespace microsim::cli {

/// Translation context of the CLI's user-facing text: Cli::tr("...").
class Cli {
  Q_DECLARE_TR_FUNCTIONS(Cli)
};

enum ExitCode : int { kExitOk = 0, kExitFailure = 1, kExitUsage = 2 };

struct Streams {
  QTextStream& out;
  QTextStream& err;
};

struct Command {
  QString name;
  QString summary;  ///< already translated
  /// Runs with the arguments after the subcommand name.
  int (*run)(const QStringList& args, Streams& io);
};

/// Every subcommand, in the order --help lists them.
std::vector<Command> commands();

/// The whole program: `arguments` excludes the program name.
int runCli(const QStringList& arguments, Streams& io);

}  // namespace microsim::cli
