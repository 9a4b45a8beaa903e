// `microsim-cli solve --scene FILE | --lattice N --solver NAME (--iterations K |
// --budget-ms T) [--cutout EPS] [--alpha A] [--momentum B] [--tolerance R] [--json OUT]`:
// builds the spring network, runs one solve from rest with the scene's controls, prints
// a short table and writes the final positions and the solve report as JSON.
#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/output_file.h"
#include "cli/spring_scene_input.h"
#include "microsim/sim/solve/solver.h"

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

struct SolveOptions {
  SceneInputOptions input;
  QCommandLineOption solver{QStringLiteral("solver"),
                            Cli::tr("The solver: %1 (default: the scene's, else qss).").arg(solverList()),
                            QStringLiteral("name")};
  QCommandLineOption iterations{QStringLiteral("iterations"), Cli::tr("Stop after <k> iterations."),
                                QStringLiteral("k")};
  QCommandLineOption budget{QStringLiteral("budget-ms"), Cli::tr("Stop after <t> milliseconds of wall-clock time."),
                            QStringLiteral("t")};
  QCommandLineOption cutout{QStringLiteral("cutout"), Cli::tr("qss per-level cutout ε in mm (0 = off)."),
                            QStringLiteral("eps")};
  QCommandLineOption alpha{QStringLiteral("alpha"), Cli::tr("qss step scale in mm per force unit (0 = automatic)."),
                           QStringLiteral("a")};
  QCommandLineOption momentum{QStringLiteral("momentum"), Cli::tr("qss momentum β in [0, 1)."), QStringLiteral("b")};
  QCommandLineOption tolerance{QStringLiteral("tolerance"), Cli::tr("Stop once the relative residual is below <r>."),
                               QStringLiteral("r")};
  QCommandLineOption json{QStringLiteral("json"), Cli::tr("Write positions and the report as JSON to <file>."),
                          QStringLiteral("file")};

  QString usage() const {
    return Cli::tr("Usage: microsim-cli solve --scene FILE | --lattice N [--solver NAME] "
                   "(--iterations K | --budget-ms T) [options]");
  }
  void declare(CommandLine& line) const {
    line.addOptions(input.all() + QList<QCommandLineOption>{solver, iterations, budget, cutout, alpha, momentum,
                                                            tolerance, json});
  }
};

// the command line's numbers and solver, checked; absent ones are nullopt
struct SolveRequest {
  std::optional<std::string> solver;
  std::optional<double> alpha, cutout, momentum, tolerance, budgetMs;
  std::optional<int> iterations;
  QString json;
};

// a number option: absent → nullopt; present but not a finite number in [low, high) → error
bool readNumber(const CommandLine& line, const QCommandLineOption& option, double low, double high,
                std::optional<double>& out) {
  if (!line.isSet(option)) return true;
  bool ok = false;
  const double v = line.value(option).toDouble(&ok);
  if (!ok || !std::isfinite(v) || v < low || v >= high) {
    line.usageError(Cli::tr("--%1 wants a number in [%2, %3), not '%4'")
                        .arg(option.names().front())
                        .arg(low)
                        .arg(high)
                        .arg(line.value(option)));
    return false;
  }
  out = v;
  return true;
}

// checked before the scene loads: a usage error must not wait for a big scene
std::optional<SolveRequest> readSolveRequest(const CommandLine& line, const SolveOptions& o) {
  SolveRequest r;
  const double inf = std::numeric_limits<double>::infinity();
  if (!readNumber(line, o.alpha, 0.0, inf, r.alpha) || !readNumber(line, o.cutout, 0.0, inf, r.cutout) ||
      !readNumber(line, o.momentum, 0.0, 1.0, r.momentum) || !readNumber(line, o.tolerance, 0.0, inf, r.tolerance) ||
      !readNumber(line, o.budget, 1e-6, inf, r.budgetMs))
    return std::nullopt;
  if (line.isSet(o.iterations)) {
    bool ok = false;
    const int k = line.value(o.iterations).toInt(&ok);
    if (!ok || k < 1) {
      line.usageError(Cli::tr("--iterations wants a whole number ≥ 1, not '%1'").arg(line.value(o.iterations)));
      return std::nullopt;
    }
    r.iterations = k;
  }
  if (line.isSet(o.solver)) {
    if (sim::makeSolver(line.value(o.solver).toStdString()) == nullptr) {
      line.usageError(Cli::tr("unknown solver '%1' (known: %2)").arg(line.value(o.solver), solverList()));
      return std::nullopt;
    }
    r.solver = line.value(o.solver).toStdString();
  }
  r.json = line.value(o.json);
  return r;
}

// the solver and its limits: the command line over the scene's settings over the defaults
struct SolveSetup {
  std::string name;
  std::unique_ptr<sim::TissueSolver> solver;
  sim::SolveBudget limits;
};

// nullopt after printing why; `exitCode` is kExitFailure (the scene's solver) or kExitUsage (no limit anywhere)
std::optional<SolveSetup> setUpSolver(const CommandLine& line, const SolveRequest& request,
                                      const sim::SceneSolverSettings& fromScene, int& exitCode) {
  SolveSetup setup;
  setup.name = request.solver.value_or(fromScene.name.value_or("qss"));
  sim::SolverParams params;
  params.alpha = request.alpha.value_or(fromScene.alpha.value_or(params.alpha));
  params.cutout = request.cutout.value_or(fromScene.cutout.value_or(params.cutout));
  params.momentum = request.momentum.value_or(fromScene.momentum.value_or(params.momentum));
  setup.solver = sim::makeSolver(setup.name, params);
  if (!setup.solver) {
    exitCode = line.failure(
        Cli::tr("the scene names an unknown solver '%1'").arg(QString::fromStdString(setup.name)));
    return std::nullopt;
  }
  const bool cliLimit = request.iterations || request.budgetMs;
  if (cliLimit) {
    if (request.iterations) setup.limits.maxIterations = *request.iterations;
    if (request.budgetMs) setup.limits.maxSeconds = *request.budgetMs / 1000.0;
  } else {
    if (fromScene.iterations) setup.limits.maxIterations = *fromScene.iterations;
    if (fromScene.budgetMs) setup.limits.maxSeconds = *fromScene.budgetMs / 1000.0;
  }
  if (request.tolerance) setup.limits.residualTolerance = *request.tolerance;
  if (!cliLimit && !fromScene.iterations && !fromScene.budgetMs && !request.tolerance) {
    exitCode = line.usageError(Cli::tr("give --iterations K or --budget-ms T (or put them in the scene's \"solver\")"));
    return std::nullopt;
  }
  return setup;
}

void printSolveReport(QTextStream& out, const sim::SpringModel& model, const std::string& solverName,
                      const sim::SolveReport& report) {
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
}

std::string solveReportJson(const sim::SpringModel& model, const sim::SpringState& state,
                            const std::string& solverName, const sim::SolveReport& report) {
  nlohmann::json doc;
  doc["solver"] = solverName;
  doc["status"] = statusKey(report.status);
  doc["iterations"] = report.iterations;
  doc["seconds"] = report.seconds;
  doc["residual"] = report.residual;
  doc["nodes"] = model.nodeCount();
  doc["links"] = model.aliveLinkCount();
  nlohmann::json positions = nlohmann::json::array();
  for (int i = 0; i < model.nodeCount(); ++i) positions.push_back({state.x(0, i), state.x(1, i), state.x(2, i)});
  doc["positions"] = std::move(positions);
  return doc.dump() + "\n";
}

// load → run → report
int solveNetwork(const CommandLine& line, const SolveOptions& options) {
  const std::optional<SolveRequest> request = readSolveRequest(line, options);
  if (!request) return kExitUsage;

  // load: the network, then the solver it is solved with
  int code = kExitOk;
  const std::optional<sim::SpringScene> scene = readSceneInput(line, options.input, code);
  if (!scene) return code;
  const std::optional<SolveSetup> setup = setUpSolver(line, *request, scene->solver, code);
  if (!setup) return code;

  // run: one solve from rest
  const sim::SpringModel& model = scene->model;
  sim::SpringState state = sim::SpringState::atRest(model);
  const sim::SolveReport report = setup->solver->solve(model, state, scene->controls, setup->limits);

  // report
  printSolveReport(line.io().out, model, setup->name, report);
  if (!request->json.isEmpty()) {
    code = writeCommandOutput(line, request->json,
                              QByteArray::fromStdString(solveReportJson(model, state, setup->name, report)));
    if (code != kExitOk) return code;
  }
  const bool failed = report.status == sim::SolveStatus::Diverged || report.status == sim::SolveStatus::InvalidInput;
  return failed ? kExitFailure : kExitOk;
}

}  // namespace

int runSolve(const QStringList& args, Streams& io) {
  return runCommand(QStringLiteral("solve"), args, io, &solveNetwork);
}

}  // namespace microsim::cli
