// `microsim-cli bench NAME [--json FILE] [--plot FILE.png] [--quick]`: runs one of the
// benchmarks in tests/bench, prints its rows (ours beside the paper's and the peer's),
// and writes the JSON rows and a PNG of its curves when asked. While it runs, the case it
// has started is a line on stderr ("speed-error: [3/11] 20^3, cold (12 s)", at most one a
// second), never on stdout or in the JSON.
#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/output_file.h"

#ifdef MICROSIM_HAVE_BENCHMARKS
#include "bench_report.h"
#include "cli/plot_png.h"
#include "cli/progress_lines.h"
#endif

#include <QElapsedTimer>

#include <sstream>

namespace microsim::cli {

namespace {

#ifdef MICROSIM_HAVE_BENCHMARKS
/// Runs `entry` with each case it starts shown on `err`, with the wall-clock seconds since
/// the run began.
bench::BenchReport runShowingProgress(const bench::BenchEntry& entry, bool quick, QTextStream& err) {
  ProgressLines lines(err);
  QElapsedTimer clock;
  clock.start();
  bench::BenchOptions options;
  options.quick = quick;
  options.progress = [&](const bench::BenchStep& step) {
    lines.step(Cli::tr("%1: [%2/%3] %4 (%5 s)")
                   .arg(QString::fromStdString(entry.name), QString::number(step.index),
                        QString::number(step.count), QString::fromStdString(step.caseName),
                        QString::number(clock.elapsed() / 1000)));
  };
  return entry.run(options);
}

// every benchmark with its one-line summary
QString benchList() {
  QString text = Cli::tr("Benchmarks:") + QLatin1Char('\n');
  for (const bench::BenchEntry& e : bench::benchRegistry())
    text += QStringLiteral("  ") + QString::fromStdString(e.name).leftJustified(14) + QString::fromStdString(e.summary) +
            QLatin1Char('\n');
  return text;
}

#endif

struct BenchCommandOptions {
  QCommandLineOption json{QStringLiteral("json"), Cli::tr("Write the rows as JSON to <file>."), QStringLiteral("file")};
  QCommandLineOption plot{QStringLiteral("plot"), Cli::tr("Draw the curves to the PNG <file>."), QStringLiteral("file")};
  QCommandLineOption quick{QStringLiteral("quick"), Cli::tr("Smaller sizes and fewer repetitions.")};
  QCommandLineOption list{QStringLiteral("list"), Cli::tr("List the benchmarks.")};

  QString usage() const { return Cli::tr("Usage: microsim-cli bench NAME [--json FILE] [--plot FILE.png] [--quick]"); }
  void declare(CommandLine& line) const {
    line.addOptions({json, plot, quick, list});
    line.addWord(QStringLiteral("name"), Cli::tr("The benchmark to run."));
#ifdef MICROSIM_HAVE_BENCHMARKS
    line.setHelpDetails(benchList());
#endif
  }
};

#ifndef MICROSIM_HAVE_BENCHMARKS
int runBenchmark(const CommandLine& line, const BenchCommandOptions&) {
  return line.failure(Cli::tr("this build has no benchmarks (configure with -DMICROSIM_BUILD_BENCHMARKS=ON)"));
}
#else
// load → run → report
int runBenchmark(const CommandLine& line, const BenchCommandOptions& options) {
  if (line.isSet(options.list)) {
    line.io().out << benchList();
    return kExitOk;
  }

  // load: the benchmark named
  const QString name = line.words().value(0);
  if (name.isEmpty()) return line.usageError(Cli::tr("name one benchmark (see --list)"));
  const bench::BenchEntry* entry = bench::findBench(name.toStdString());
  if (entry == nullptr) return line.usageError(Cli::tr("unknown benchmark '%1' (see --list)").arg(name));

  // run
  const bench::BenchReport report = runShowingProgress(*entry, line.isSet(options.quick), line.io().err);

  // report: the table, the JSON rows, the plot
  std::ostringstream table;
  bench::printTable(table, report.rows);
  line.io().out << QString::fromStdString(table.str());
  if (line.isSet(options.json)) {
    const int code =
        writeCommandOutput(line, line.value(options.json), QByteArray::fromStdString(bench::toJson(report.rows)));
    if (code != kExitOk) return code;
  }
  if (line.isSet(options.plot)) {
    if (report.plots.empty())
      line.warning(Cli::tr("'%1' has no curves to plot").arg(name));
    else if (!writePlotPng(report.plots, line.value(options.plot)))
      return line.failure(Cli::tr("cannot write the plot %1").arg(line.value(options.plot)));
  }
  return kExitOk;
}
#endif

}  // namespace

int runBench(const QStringList& args, Streams& io) {
  return runCommand(QStringLiteral("bench"), args, io, &runBenchmark);
}

}  // namespace microsim::cli
