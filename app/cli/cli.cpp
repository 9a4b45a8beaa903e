#include "cli/cli.h"

#include "cli/commands.h"

namespace microsim::cli {

std::vector<Command> commands() {
  return {
      {QStringLiteral("solve"), Cli::tr("solve a spring network (scene file or lattice box)"), &runSolve},
      {QStringLiteral("export"), Cli::tr("export the spring network a scene builds"), &runExport},
      {QStringLiteral("bench"), Cli::tr("run a benchmark (beside the paper's figures)"), &runBench},
      {QStringLiteral("run"), Cli::tr("run a scene on recorded or scripted input (hash, events, timings)"), &runRun},
      {QStringLiteral("track"), Cli::tr("record what an OpenIGTLink tracker sends"), &runTrack},
      {QStringLiteral("calibrate"), Cli::tr("pivot calibration or tracker-to-scene registration from a file"), &runCalibrate},
      {QStringLiteral("score"), Cli::tr("score a recorded attempt with a rubric (and store it in the history)"), &runScore},
      {QStringLiteral("db"), Cli::tr("the history database: migrate, backup, restore, export CSV, trainees"), &runDb},
  };
}

namespace {

void printUsage(QTextStream& out) {
  out << Cli::tr("Usage: microsim-cli <command> [options]") << '\n'
      << Cli::tr("       microsim-cli --version | --help") << "\n\n"
      << Cli::tr("Commands:") << '\n';
  for (const Command& c : commands()) out << "  " << c.name.leftJustified(10) << c.summary << '\n';
  out << '\n'
      << Cli::tr("Run 'microsim-cli <command> --help' for a command's options.") << '\n';
}

}  // namespace

int runCli(const QStringList& arguments, Streams& io) {
  if (arguments.isEmpty()) {
    printUsage(io.err);
    return kExitUsage;
  }
  const QString& first = arguments.front();
  if (first == QLatin1String("--version") || first == QLatin1String("-v")) {
    io.out << "microsim-cli " << MICROSIM_VERSION << '\n';
    return kExitOk;
  }
  if (first == QLatin1String("--help") || first == QLatin1String("-h") || first == QLatin1String("help")) {
    printUsage(io.out);
    return kExitOk;
  }
  for (const Command& c : commands()) {
    if (c.name == first) return c.run(arguments.mid(1), io);
  }
  io.err << Cli::tr("microsim-cli: unknown command '%1'").arg(first) << '\n';
  printUsage(io.err);
  return kExitUsage;
}

}  // namespace microsim::cli
