#pragma once
// A recording named on the command line (`run --input`, `score --recording`): read for what
// the command does with it, and the scene it was made on found again.
#include "cli/command_line.h"

#include "microsim/sim/scene/recording.h"

#include <optional>

namespace microsim::cli {

/// What the command does with the frames: said in the warning about a recording cut short.
enum class RecordingUse { Replay, Score };

struct RecordingInput {
  QString path;
  sim::Recording recording;
  bool truncated = false;  ///< no end record: the complete frames of an unfinished attempt
};

/// Reads `path`. A recording cut short gives its complete frames, with a warning; any other
/// error is printed through `line` and gives nullopt (the command fails: exit 1).
std::optional<RecordingInput> readRecordingInput(const CommandLine& line, const QString& path, RecordingUse use);

/// The scene file `input` was made on, found where it was, beside the recording or among the
/// shipped scenes (sim::locateRecordedScene); a warning when the file found was changed
/// since. nullopt after printing why, with `exitCode`: kExitUsage when the recording names
/// no scene (only --scene can say), kExitFailure when its scene is in none of those places.
std::optional<QString> sceneOfRecording(const CommandLine& line, const RecordingInput& input, int& exitCode);

}  // namespace microsim::cli
