#pragma once
// The subcommands' entry points, one file each (solve_command.cpp, ...).
#include "cli/cli.h"

namespace microsim::cli {

int runSolve(const QStringList& args, Streams& io);
int runExport(const QStringList& args, Streams& io);
int runBench(const QStringList& args, Streams& io);
int runRun(const QStringList& args, Streams& io);
int runTrack(const QStringList& args, Streams& io);
int runCalibrate(const QStringList& args, Streams& io);
int runScore(const QStringList& args, Streams& io);
int runDb(const QStringList& args, Streams& io);

}  // namespace microsim::cli
