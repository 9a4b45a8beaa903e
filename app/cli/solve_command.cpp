// `microsim-cli solve --scene FILE | --lattice N --solver NAME (--iterations K |
// --budget-ms T) [--cutout EPS] [--alpha A] [--momentum B] [--tolerance R] [--json OUT]`:
// builds the spring network, runs one solve from rest with the scene's controls, prints
// a short table and writes the final positions and the solve report as JSON.
#include "cli/commands.h"
#include "cli/output_file.h"

#include "cli/spring_scene_input.h"
#include "microsim/sim/solve/solver.h"

#include <QCommandLineParser>
#include <QFile>

#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>

namespace microsim::cli {

namespace {

const char* statusKey(sim::SolveStatus s) {
  switch (s) {
    case sim::SolveStatus::Converged:
      return "converged";
    case sim::SolveStatus::IterationLimit:
      return "iteration-limit";
    case sim::SolveStatus::TimeLimit:
      return "time-limit";
    case sim::SolveStatus::Diverged:
      return "diverged";
    case sim::SolveStatus::InvalidInput:
      return "invalid-input";
  }
  return "";
}

QString statusText(sim::SolveStatus s) {
  switch (s) {
    case sim::SolveStatus::Converged:
      return Cli::tr("converged");
    case sim::SolveStatus::IterationLimit:
      return Cli::tr("iteration limit");
    case sim::SolveStatus::TimeLimit:
      return Cli::tr("time limit");
    case sim::SolveStatus::Diverged:
      return Cli::tr("diverged (state restored)");
    case sim::SolveStatus::InvalidInput:
      return Cli::tr("invalid input");
  }
  return {};
}

QString solverList() {
  QStringList names;
  for (const std::string& n : sim::solverNames()) names << QString::fromStdString(n);
  return names.join(QStringLiteral(", "));
}

// a number option: absent → nullopt; present but not a finite number in [low, high) → error
bool readNumber(const QCommandLineParser& parser, const QCommandLineOption& option, double low,
                double high, std::optional<double>& out, Streams& io) {
  if (!parser.isSet(option)) return true;
  bool ok = false;
  const double v = parser.value(option).toDouble(&ok);
  if (!ok || !std::isfinite(v) || v < low || v >= high) {
    io.err << QStringLiteral("microsim-cli solve: ")
           << Cli::tr("--%1 wants a number in [%2, %3), not '%4'")
                  .arg(option.names().front())
                  .arg(low)
                  .arg(high)
                  .arg(parser.value(option))
           << '\n';
    return false;
  }
  out = v;
  return true;
}

}  // namespace

int runSolve(const QStringList& args, Streams& io) {
  QCommandLineParser parser;
  const SceneInputOptions input;
  const QCommandLineOption solverOpt(
      QStringLiteral("solver"),
      Cli::tr("The solver: %1 (default: the scene's, else qss).").arg(solverList()),
      QStringLiteral("name"));
  const QCommandLineOption iterations(QStringLiteral("iterations"),
                                      Cli::tr("Stop after <k> iterations."), QStringLiteral("k"));
  const QCommandLineOption budget(QStringLiteral("budget-ms"),
                                  Cli::tr("Stop after <t> milliseconds of wall-clock time."),
                                  QStringLiteral("t"));
  const QCommandLineOption cutout(QStringLiteral("cutout"),
                                  Cli::tr("qss per-level cutout ε in mm (0 = off)."),
                                  QStringLiteral("eps"));
  const QCommandLineOption alpha(QStringLiteral("alpha"),
                                 Cli::tr("qss step scale in mm per force unit (0 = automatic)."),
                                 QStringLiteral("a"));
  const QCommandLineOption momentum(QStringLiteral("momentum"),
                                    Cli::tr("qss momentum β in [0, 1)."), QStringLiteral("b"));
  const QCommandLineOption tolerance(QStringLiteral("tolerance"),
                                     Cli::tr("Stop once the relative residual is below <r>."),
                                     QStringLiteral("r"));
  const QCommandLineOption json(QStringLiteral("json"),
                                Cli::tr("Write positions and the report as JSON to <file>."),
                                QStringLiteral("file"));
  const QCommandLineOption help(QStringList{QStringLiteral("h"), QStringLiteral("help")},
                                Cli::tr("Show this help."));
  input.addTo(parser);
  parser.addOptions(
      {solverOpt, iterations, budget, cutout, alpha, momentum, tolerance, json, help});
  const QString prefix = QStringLiteral("microsim-cli solve: ");
  if (!parser.parse(QStringList{QStringLiteral("solve")} + args)) {
    io.err << prefix << parser.errorText() << '\n';
    return kExitUsage;
  }
  if (parser.isSet(help)) {
    io.out << Cli::tr(
                  "Usage: microsim-cli solve --scene FILE | --lattice N [--solver NAME] "
                  "(--iterations K | --budget-ms T) [options]")
           << "\n\n"
           << parser.helpText().section(QLatin1Char('\n'), 2);
    return kExitOk;
  }
  if (!parser.positionalArguments().isEmpty()) {
    io.err << prefix
           << Cli::tr("unexpected argument '%1'").arg(parser.positionalArguments().front()) << '\n';
    return kExitUsage;
  }

  // command-line numbers first: a usage error must not wait for a big scene to load
  std::optional<double> alphaV, cutoutV, momentumV, toleranceV, budgetV, iterationsV;
  const double inf = std::numeric_limits<double>::infinity();
  if (!readNumber(parser, alpha, 0.0, inf, alphaV, io) ||
      !readNumber(parser, cutout, 0.0, inf, cutoutV, io) ||
      !readNumber(parser, momentum, 0.0, 1.0, momentumV, io) ||
      !readNumber(parser, tolerance, 0.0, inf, toleranceV, io) ||
      !readNumber(parser, budget, 1e-6, inf, budgetV, io))
    return kExitUsage;
  if (parser.isSet(iterations)) {
    bool ok = false;
    const int k = parser.value(iterations).toInt(&ok);
    if (!ok || k < 1) {
      io.err << prefix
             << Cli::tr("--iterations wants a whole number ≥ 1, not '%1'")
                    .arg(parser.value(iterations))
             << '\n';
      return kExitUsage;
    }
    iterationsV = k;
  }
  if (parser.isSet(solverOpt)) {
    const std::string name = parser.value(solverOpt).toStdString();
    if (sim::makeSolver(name) == nullptr) {
      io.err
          << prefix
          << Cli::tr("unknown solver '%1' (known: %2)").arg(parser.value(solverOpt), solverList())
          << '\n';
      return kExitUsage;
    }
  }

  int code = kExitOk;
  std::optional<sim::SpringScene> scene =
      readSceneInput(parser, input, QStringLiteral("solve"), io, code);
  if (!scene) return code;

  // command line over scene settings over defaults
  const sim::SceneSolverSettings& fromScene = scene->solver;
  const std::string solverName = parser.isSet(solverOpt) ? parser.value(solverOpt).toStdString()
                                                         : fromScene.name.value_or("qss");
  sim::SolverParams params;
  params.alpha = alphaV.value_or(fromScene.alpha.value_or(params.alpha));
  params.cutout = cutoutV.value_or(fromScene.cutout.value_or(params.cutout));
  params.momentum = momentumV.value_or(fromScene.momentum.value_or(params.momentum));
  std::unique_ptr<sim::TissueSolver> solver = sim::makeSolver(solverName, params);
  if (!solver) {
    io.err
        << prefix
        << Cli::tr("the scene names an unknown solver '%1'").arg(QString::fromStdString(solverName))
        << '\n';
    return kExitFailure;
  }
  sim::SolveBudget limits;
  const bool cliLimit = iterationsV || budgetV;
  if (cliLimit) {
    if (iterationsV) limits.maxIterations = static_cast<int>(*iterationsV);
    if (budgetV) limits.maxSeconds = *budgetV / 1000.0;
  } else {
    if (fromScene.iterations) limits.maxIterations = *fromScene.iterations;
    if (fromScene.budgetMs) limits.maxSeconds = *fromScene.budgetMs / 1000.0;
  }
  if (toleranceV) limits.residualTolerance = *toleranceV;
  if (!cliLimit && !fromScene.iterations && !fromScene.budgetMs && !toleranceV) {
    io.err << prefix
           << Cli::tr(
                  "give --iterations K or --budget-ms T (or put them in the scene's \"solver\")")
           << '\n';
    return kExitUsage;
  }

  // one solve from rest
  const sim::SpringModel& model = scene->model;
  sim::SpringState state = sim::SpringState::atRest(model);
  const sim::SolveReport report = solver->solve(model, state, scene->controls, limits);

  QTextStream& out = io.out;
  const auto row = [&out](const QString& label, const QString& value) {
    out << "  " << label.leftJustified(12) << value << '\n';
  };
  row(Cli::tr("nodes"), QString::number(model.nodeCount()));
  row(Cli::tr("links"), QString::number(model.aliveLinkCount()));
  row(Cli::tr("solver"), QString::fromStdString(solverName));
  row(Cli::tr("iterations"), QString::number(report.iterations));
  row(Cli::tr("seconds"), QString::number(report.seconds, 'g', 4));
  row(Cli::tr("residual"), QString::number(report.residual, 'g', 4));
  row(Cli::tr("status"), statusText(report.status));

  if (parser.isSet(json)) {
    nlohmann::json doc;
    doc["solver"] = solverName;
    doc["status"] = statusKey(report.status);
    doc["iterations"] = report.iterations;
    doc["seconds"] = report.seconds;
    doc["residual"] = report.residual;
    doc["nodes"] = model.nodeCount();
    doc["links"] = model.aliveLinkCount();
    nlohmann::json positions = nlohmann::json::array();
    for (int i = 0; i < model.nodeCount(); ++i)
      positions.push_back({state.x(0, i), state.x(1, i), state.x(2, i)});
    doc["positions"] = std::move(positions);
    QString why;
    if (!writeOutputFile(parser.value(json), QByteArray::fromStdString(doc.dump() + "\n"), why)) {
      io.err << prefix << Cli::tr("cannot write %1: %2").arg(parser.value(json), why)
             << '\n';
      return kExitFailure;
    }
  }
  const bool failed = report.status == sim::SolveStatus::Diverged ||
                      report.status == sim::SolveStatus::InvalidInput;
  return failed ? kExitFailure : kExitOk;
}

}  // namespace microsim::cli
