// `microsim-cli bench NAME [--json FILE] [--plot FILE.png] [--quick]`: runs one of the
// benchmarks in tests/bench, prints its rows (ours beside the paper's and the peer's),
// and writes the JSON rows and a PNG of its curves when asked. While it runs, the case it
// has started is a line on stderr ("speed-error: [3/11] 20^3, cold (12 s)", at most one a
// second), never on stdout or in the JSON.
#include "cli/commands.h"
#include "cli/output_file.h"

#ifdef MICROSIM_HAVE_BENCHMARKS
#include "bench_report.h"
#include "cli/plot_png.h"
#include "cli/progress_lines.h"
#endif

#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QFile>

#include <sstream>

namespace microsim::cli {

#ifdef MICROSIM_HAVE_BENCHMARKS
namespace {

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

}  // namespace
#endif

int runBench(const QStringList& args, Streams& io) {
#ifndef MICROSIM_HAVE_BENCHMARKS
  Q_UNUSED(args);
  io.err << Cli::tr("microsim-cli: this build has no benchmarks (configure with -DMICROSIM_BUILD_BENCHMARKS=ON)") << '\n';
  return kExitFailure;
#else
  QCommandLineParser parser;
  const QCommandLineOption json(QStringLiteral("json"), Cli::tr("Write the rows as JSON to <file>."), QStringLiteral("file"));
  const QCommandLineOption plot(QStringLiteral("plot"), Cli::tr("Draw the curves to the PNG <file>."), QStringLiteral("file"));
  const QCommandLineOption quick(QStringLiteral("quick"), Cli::tr("Smaller sizes and fewer repetitions."));
  const QCommandLineOption list(QStringLiteral("list"), Cli::tr("List the benchmarks."));
  const QCommandLineOption help(QStringList{QStringLiteral("h"), QStringLiteral("help")}, Cli::tr("Show this help."));
  parser.addOptions({json, plot, quick, list, help});
  parser.addPositionalArgument(QStringLiteral("name"), Cli::tr("The benchmark to run."));
  if (!parser.parse(QStringList{QStringLiteral("bench")} + args)) {
    io.err << "microsim-cli bench: " << parser.errorText() << '\n';
    return kExitUsage;
  }

  if (parser.isSet(help) || parser.isSet(list)) {
    QTextStream& out = io.out;
    if (parser.isSet(help))
      out << Cli::tr("Usage: microsim-cli bench NAME [--json FILE] [--plot FILE.png] [--quick]") << "\n\n";
    out << Cli::tr("Benchmarks:") << '\n';
    for (const bench::BenchEntry& e : bench::benchRegistry())
      out << "  " << QString::fromStdString(e.name).leftJustified(14) << QString::fromStdString(e.summary) << '\n';
    return kExitOk;
  }

  const QStringList names = parser.positionalArguments();
  if (names.size() != 1) {
    io.err << Cli::tr("microsim-cli bench: name one benchmark (see --list)") << '\n';
    return kExitUsage;
  }
  const bench::BenchEntry* entry = bench::findBench(names.front().toStdString());
  if (entry == nullptr) {
    io.err << Cli::tr("microsim-cli bench: unknown benchmark '%1' (see --list)").arg(names.front()) << '\n';
    return kExitUsage;
  }

  const bench::BenchReport report = runShowingProgress(*entry, parser.isSet(quick), io.err);

  std::ostringstream table;
  bench::printTable(table, report.rows);
  io.out << QString::fromStdString(table.str());

  if (parser.isSet(json)) {
    QString why;
    if (!writeOutputFile(parser.value(json), QByteArray::fromStdString(bench::toJson(report.rows)), why)) {
      io.err << Cli::tr("microsim-cli bench: cannot write %1: %2").arg(parser.value(json), why) << '\n';
      return kExitFailure;
    }
  }
  if (parser.isSet(plot)) {
    if (report.plots.empty()) {
      io.err << Cli::tr("microsim-cli bench: '%1' has no curves to plot").arg(names.front()) << '\n';
    } else if (!writePlotPng(report.plots, parser.value(plot))) {
      io.err << Cli::tr("microsim-cli bench: cannot write the plot %1").arg(parser.value(plot)) << '\n';
      return kExitFailure;
    }
  }
  return kExitOk;
#endif
}

}  // namespace microsim::cli
