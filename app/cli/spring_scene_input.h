#pragma once
// What `solve` and `export` both read: a spring network from `--scene FILE` or the
// paper's benchmark box from `--lattice N` (bottom face fixed, middle node of the top
// face displaced +1 mm in z), and the words for a scene file's errors.
#include "cli/command_line.h"

#include "microsim/sim/scene/spring_scene.h"

#include <optional>

namespace microsim::cli {

struct SceneInputOptions {
  QCommandLineOption scene{QStringLiteral("scene"),
                           Cli::tr("Read the spring network from the scene <file>."),
                           QStringLiteral("file")};
  QCommandLineOption lattice{
      QStringLiteral("lattice"),
      Cli::tr("Use the paper's N×N×N lattice box (bottom fixed, top middle node pulled up 1 mm)."),
      QStringLiteral("N")};
  QCommandLineOption stiffness{QStringLiteral("stiffness"),
                               Cli::tr("Link stiffness of the --lattice box in g/s² (default 10)."),
                               QStringLiteral("k")};

  QList<QCommandLineOption> all() const { return {scene, lattice, stiffness}; }
};

/// The scene named on the command line, or nullopt after printing why through `line`;
/// `exitCode` is then kExitUsage (bad arguments) or kExitFailure (bad scene file).
std::optional<sim::SpringScene> readSceneInput(const CommandLine& line, const SceneInputOptions& options,
                                               int& exitCode);

/// One line describing a scene error: "FILE:LINE:COLUMN: what is wrong (field PATH)".
QString describeSceneError(const sim::SceneError& error);

}  // namespace microsim::cli
