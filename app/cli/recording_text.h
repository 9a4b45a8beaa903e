#pragma once
// The words for a recording's read/write errors, shared by the commands that read them.
#include "cli/cli.h"

#include "microsim/sim/scene/recording.h"

namespace microsim::cli {

QString recordingErrorText(sim::RecordingError e);

}  // namespace microsim::cli
