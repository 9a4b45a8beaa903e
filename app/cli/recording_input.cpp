#include "cli/recording_input.h"

#include "cli/recording_text.h"
#include "lesson/lesson.h"
#include "microsim/sim/scene/recorded_scene.h"

#include <QDir>

#include <nlohmann/json.hpp>

namespace microsim::cli {

namespace {

// a version-1 recording names no scene in its header; the app's wrote it in the metadata,
// as JSON {"scene": PATH} (no digest)
sim::RecordedScene sceneFromVersion1Metadata(const std::string& metadata) {
  const nlohmann::json meta = nlohmann::json::parse(metadata, nullptr, false);
  if (!meta.is_object() || !meta.contains("scene") || !meta["scene"].is_string()) return {};
  return {meta["scene"].get<std::string>(), 0};
}

// the shipped scenes: beside the shipped lessons, which name theirs "../scenes/NAME.json"
QString shippedScenesDirectory() {
  return QDir::cleanPath(QDir(lesson::lessonsDirectory()).filePath(QStringLiteral("../scenes")));
}

}  // namespace

std::optional<RecordingInput> readRecordingInput(const CommandLine& line, const QString& path, RecordingUse use) {
  RecordingInput input;
  input.path = path;
  const sim::RecordingStatus status = sim::readRecording(path.toStdString(), input.recording);
  input.truncated = status.error == sim::RecordingError::Truncated;
  if (!status.ok() && !input.truncated) {
    line.failure(path + QStringLiteral(": ") + recordingErrorText(status.error) + QLatin1Char(' ') +
                 Cli::tr("(at byte %1)").arg(status.offset));
    return std::nullopt;
  }
  if (input.truncated) {
    const int frames = static_cast<int>(input.recording.frames.size());
    line.warning(path + QStringLiteral(": ") + recordingErrorText(status.error) + QStringLiteral("; ") +
                 (use == RecordingUse::Replay ? Cli::tr("replaying its %n complete frame(s)", nullptr, frames)
                                              : Cli::tr("scoring its %n complete frame(s)", nullptr, frames)));
  }
  return input;
}

std::optional<QString> sceneOfRecording(const CommandLine& line, const RecordingInput& input, int& exitCode) {
  const sim::RecordedScene recorded = input.recording.scene.known()
                                          ? input.recording.scene
                                          : sceneFromVersion1Metadata(input.recording.metadata);
  if (!recorded.known()) {
    exitCode = line.usageError(Cli::tr("the recording names no scene: give --scene FILE"));
    return std::nullopt;
  }
  const sim::SceneLocation found = sim::locateRecordedScene(recorded, input.path.toStdString(),
                                                            {shippedScenesDirectory().toStdString()});
  const QString named = QString::fromStdString(recorded.path);
  if (found.match == sim::SceneMatch::Missing) {
    QStringList looked;
    for (const std::string& place : found.looked) looked << QString::fromStdString(place);
    exitCode = line.failure(Cli::tr("the recording was made on the scene %1, which is not there, not beside the "
                                    "recording and not among the shipped scenes (looked at: %2); give --scene FILE")
                                .arg(named, looked.join(QStringLiteral(", "))));
    return std::nullopt;
  }
  const QString path = QString::fromStdString(found.path);
  if (found.match == sim::SceneMatch::Changed)
    line.warning(Cli::tr("%1 has changed since the recording was made on it (%2): the replay may differ from "
                         "the attempt")
                     .arg(path, named));
  exitCode = kExitOk;
  return path;
}

}  // namespace microsim::cli
