#include "cli/command_line.h"

namespace microsim::cli {

CommandLine::CommandLine(const QString& command, const QString& usage, Streams& io)
    : command_(command),
      usage_(usage),
      io_(io),
      help_(QStringList{QStringLiteral("h"), QStringLiteral("help")}, Cli::tr("Show this help.")) {
  parser_.addOption(help_);
}

void CommandLine::addOptions(const QList<QCommandLineOption>& options) {
  parser_.addOptions(options);
}

void CommandLine::addWord(const QString& name, const QString& description) {
  parser_.addPositionalArgument(name, description);
  ++wordCount_;
}

void CommandLine::setHelpDetails(const QString& details) {
  details_ = details;
}

std::optional<int> CommandLine::parse(const QStringList& args) {
  // QCommandLineParser takes the program's name first
  if (!parser_.parse(QStringList{command_} + args)) return usageError(parser_.errorText());
  if (parser_.isSet(help_)) {
    // Qt's own first line ("Usage: run [options]") gives way to the command's synopsis
    io_.out << usage_ << "\n\n" << parser_.helpText().section(QLatin1Char('\n'), 2);
    if (!details_.isEmpty()) io_.out << '\n' << details_;
    return kExitOk;
  }
  const QStringList given = parser_.positionalArguments();
  if (given.size() > wordCount_)
    return usageError(Cli::tr("unexpected argument '%1'").arg(given.at(wordCount_)));
  return std::nullopt;
}

QString CommandLine::prefix() const {
  return QStringLiteral("microsim-cli %1: ").arg(command_);
}

int CommandLine::usageError(const QString& message) const {
  io_.err << prefix() << message << '\n';
  return kExitUsage;
}

int CommandLine::failure(const QString& message) const {
  io_.err << prefix() << message << '\n';
  return kExitFailure;
}

void CommandLine::warning(const QString& message) const {
  io_.err << prefix() << Cli::tr("warning: %1").arg(message) << '\n';
}

}  // namespace microsim::cli
