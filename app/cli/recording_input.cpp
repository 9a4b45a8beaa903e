#include "cli/recording_input.h"

#include "cli/recording_text.h"

namespace microsim::cli {

std::optional<RecordingInput> readRecordingInput(const CommandLine& line, const QString& path,
                                                 RecordingUse use) {
  RecordingInput input;
  const sim::RecordingStatus status = sim::readRecording(path.toStdString(), input.recording);
  input.truncated = status.error == sim::RecordingError::Truncated;
  if (!status.ok() && !input.truncated) {
    line.failure(path + QStringLiteral(": ") + recordingErrorText(status.error) + QLatin1Char(' ') +
                 Cli::tr("(at byte %1)").arg(status.offset));
    return std::nullopt;
  }
  if (input.truncated) {
    const int frames = static_cast<int>(input.recording.frames.size());
    line.warning(path + QStringLiteral(": ") + recordingErrorText(status.error) +
                 QStringLiteral("; ") +
                 (use == RecordingUse::Replay
                      ? Cli::tr("replaying its %n complete frame(s)", nullptr, frames)
                      : Cli::tr("scoring its %n complete frame(s)", nullptr, frames)));
  }
  return input;
}

}  // namespace microsim::cli
