#pragma once
// A recording named on the command line (`run --input`, `score --recording`), read for
// what the command does with it.
#include "cli/command_line.h"

#include "microsim/sim/scene/recording.h"

#include <optional>

namespace microsim::cli {

/// What the command does with the frames: said in the warning about a recording cut short.
enum class RecordingUse { Replay, Score };

struct RecordingInput {
  sim::Recording recording;
  bool truncated = false;  ///< no end record: the complete frames of an unfinished attempt
};

/// Reads `path`. A recording cut short gives its complete frames, with a warning; any other
/// error is printed through `line` and gives nullopt (the command fails: exit 1).
std::optional<RecordingInput> readRecordingInput(const CommandLine& line, const QString& path,
                                                 RecordingUse use);

}  // namespace microsim::cli
