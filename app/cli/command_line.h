#pragma once
// One shape for every subcommand's command line. A command declares its usage line, its
// options and the words it takes in an options struct, and runCommand (below) does the
// prologue every command shares; parse() is what each command used to repeat:
//   --help        the usage line, the options and words, any details: stdout, exit 0
//   an unknown option, an option without its value, a word beyond the declared ones
//                 "microsim-cli <command>: <what is wrong>" on stderr, exit 2
// After parse() the command reads its values and reports through the same prefix:
// usageError() for a command line that is wrong (exit 2), failure() for a command that ran
// and failed (exit 1), warning() for what it goes on despite.
#include "cli/cli.h"

#include <QCommandLineOption>
#include <QCommandLineParser>

#include <optional>

namespace microsim::cli {

class CommandLine {
 public:
  /// `command` is the subcommand's name ("run"); `usage` its translated synopsis line.
  CommandLine(const QString& command, const QString& usage, Streams& io);

  void addOptions(const QList<QCommandLineOption>& options);
  /// A word the command takes after its name ("action", "name"), in order; any word
  /// beyond the declared ones is refused. Whether a word is required is the command's call.
  void addWord(const QString& name, const QString& description);
  /// Text --help prints after the options (e.g. what NAME may be).
  void setHelpDetails(const QString& details);

  /// Parses the arguments after the command's name. The exit code when the command is done
  /// already (kExitOk after --help, kExitUsage after an error, printed); nullopt to go on.
  std::optional<int> parse(const QStringList& args);

  bool isSet(const QCommandLineOption& option) const { return parser_.isSet(option); }
  QString value(const QCommandLineOption& option) const { return parser_.value(option); }
  /// The words given, in order (no more than were declared).
  QStringList words() const { return parser_.positionalArguments(); }

  /// "microsim-cli <command>: " — every line the command writes to stderr starts so.
  QString prefix() const;
  /// Prints `message` with the prefix; kExitUsage.
  int usageError(const QString& message) const;
  /// Prints `message` with the prefix; kExitFailure.
  int failure(const QString& message) const;
  /// Prints "warning: `message`" with the prefix; the command goes on.
  void warning(const QString& message) const;

  Streams& io() const { return io_; }

 private:
  QString command_;
  QString usage_;
  QString details_;
  int wordCount_ = 0;
  Streams& io_;
  QCommandLineParser parser_;
  QCommandLineOption help_;
};

/// The prologue of every subcommand, written once. `Options` holds the command's options
/// (made here, once the translator is installed, so that --help is translated) and gives
/// `QString usage() const` and `void declare(CommandLine&) const`; the arguments after the
/// command's name are parsed (--help, stray words, unknown options: done here), and `body`
/// does the command's work on the parsed line: load → run → report.
template <class Options>
int runCommand(const QString& command, const QStringList& args, Streams& io,
               int (*body)(const CommandLine& line, const Options& options)) {
  const Options options;
  CommandLine line(command, options.usage(), io);
  options.declare(line);
  if (const std::optional<int> done = line.parse(args)) return *done;
  return body(line, options);
}

}  // namespace microsim::cli
