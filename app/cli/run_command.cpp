// `microsim-cli run --scene S [--input REC | --script stitch|back-wall-catch] [--record REC]
// [--frames N] [--realtime] [--json OUT]`: builds the scene, feeds it one InputFrame per fixed
// step (from a recording, from a scripted pass, or idle hands), and prints the final state hash,
// the events and the per-stage step times (median, p99, max). With --input and no --scene,
// the scene is the one the recording was made on.
#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/output_file.h"
#include "cli/recording_input.h"
#include "cli/recording_text.h"
#include "cli/run_report.h"
#include "cli/spring_scene_input.h"
#include "microsim/sim/scene/back_wall_catch_script.h"
#include "microsim/sim/scene/recorded_scene.h"
#include "microsim/sim/scene/recording.h"
#include "microsim/sim/scene/scene.h"
#include "microsim/sim/scene/stitch_script.h"

#include <nlohmann/json.hpp>

#include <array>
#include <string>
#include <vector>

namespace microsim::cli {

namespace {

// the inputs --script generates, by name: each a scene's frames, empty when the scene lacks
// what the script needs (a severed vessel, a curved needle, two forceps)
struct ScriptedInput {
  const char* name;
  sim::Recording (*frames)(const sim::SceneDef&);
};
constexpr std::array<ScriptedInput, 2> kScriptedInputs{{
    {"stitch", [](const sim::SceneDef& scene) { return sim::scriptedStitch(scene); }},
    {"back-wall-catch",
     [](const sim::SceneDef& scene) { return sim::scriptedBackWallCatch(scene); }},
}};

const ScriptedInput* scriptedInput(const QString& name) {
  for (const ScriptedInput& s : kScriptedInputs)
    if (name == QLatin1String(s.name)) return &s;
  return nullptr;
}

struct RunOptions {
  QCommandLineOption scene{QStringLiteral("scene"),
                           Cli::tr("The scene <file> to run (default with --input: the one the recording names)."),
                           QStringLiteral("file")};
  QCommandLineOption input{QStringLiteral("input"), Cli::tr("Replay the input frames of the recording <file>."),
                           QStringLiteral("file")};
  QCommandLineOption script{QStringLiteral("script"),
                            Cli::tr("Generate the input instead: 'stitch' (one scripted stitch) or "
                                    "'back-wall-catch' (a pass that catches the back wall)."),
                            QStringLiteral("name")};
  QCommandLineOption record{QStringLiteral("record"), Cli::tr("Record every input frame to <file>."),
                            QStringLiteral("file")};
  QCommandLineOption frames{QStringLiteral("frames"), Cli::tr("Run <n> steps (default: every input frame, else 100)."),
                            QStringLiteral("n")};
  QCommandLineOption realtime{QStringLiteral("realtime"),
                              Cli::tr("Stop each tissue solve at the step budget (not reproducible).")};
  QCommandLineOption json{QStringLiteral("json"), Cli::tr("Write the hash, events and timings as JSON to <file>."),
                          QStringLiteral("file")};

  QString usage() const {
    return Cli::tr(
        "Usage: microsim-cli run (--scene FILE [--input REC | --script NAME] | --input REC) "
        "[--record REC] [--frames N] [--json OUT]");
  }
  void declare(CommandLine& line) const { line.addOptions({scene, input, script, record, frames, realtime, json}); }
};

// what the command line asks for, checked
struct RunRequest {
  QString scene;        ///< empty: the one the --input recording names
  QString input;       ///< a recording to replay; empty: none
  QString script;      ///< the scripted pass ("stitch", "back-wall-catch"); empty: none
  QString record;      ///< where to record the frames fed; empty: nowhere
  long long frames = -1;  ///< steps to run; -1: every input frame (100 without input)
  bool realtime = false;
  QString json;
};

std::optional<RunRequest> readRunRequest(const CommandLine& line, const RunOptions& o) {
  if (!line.isSet(o.scene) && !line.isSet(o.input)) {
    line.usageError(Cli::tr("give --scene FILE, or --input REC to replay it on the scene it was recorded on"));
    return std::nullopt;
  }
  if (line.isSet(o.input) && line.isSet(o.script)) {
    line.usageError(Cli::tr("--input and --script exclude each other"));
    return std::nullopt;
  }
  if (line.isSet(o.script) && !scriptedInput(line.value(o.script))) {
    QStringList known;
    for (const ScriptedInput& s : kScriptedInputs) known << QLatin1String(s.name);
    line.usageError(Cli::tr("unknown script '%1' (known: %2)")
                        .arg(line.value(o.script), known.join(QStringLiteral(", "))));
    return std::nullopt;
  }
  RunRequest r;
  if (line.isSet(o.frames)) {
    bool ok = false;
    r.frames = line.value(o.frames).toLongLong(&ok);
    if (!ok || r.frames < 0) {
      line.usageError(Cli::tr("--frames wants a whole number ≥ 0, not '%1'").arg(line.value(o.frames)));
      return std::nullopt;
    }
  }
  r.scene = line.value(o.scene);
  r.input = line.value(o.input);
  r.script = line.value(o.script);
  r.record = line.value(o.record);
  r.realtime = line.isSet(o.realtime);
  r.json = line.value(o.json);
  return r;
}

// the scene and the frames it is fed
struct RunInput {
  QString sceneFile;
  sim::SceneDef scene;
  std::vector<sim::InputFrame> feed;
};

// nullopt after printing why: `exitCode` is kExitFailure, or kExitUsage when only --scene can name the scene
std::optional<RunInput> loadRunInput(const CommandLine& line, const RunRequest& request, int& exitCode) {
  exitCode = kExitFailure;
  // the recording first: it names the scene it was made on
  std::optional<RecordingInput> replay;
  if (!request.input.isEmpty()) {
    replay = readRecordingInput(line, request.input, RecordingUse::Replay);
    if (!replay) return std::nullopt;
  }
  const std::optional<QString> sceneFile =
      request.scene.isEmpty() ? sceneOfRecording(line, *replay, exitCode) : request.scene;
  if (!sceneFile) return std::nullopt;
  sim::SceneDefLoad load = sim::loadSceneDef(sceneFile->toStdString());
  if (auto* e = std::get_if<sim::SceneError>(&load)) {
    exitCode = line.failure(describeSceneError(*e));
    return std::nullopt;
  }
  RunInput run{*sceneFile, std::get<sim::SceneDef>(std::move(load)), {}};
  if (replay) {
    run.feed = std::move(replay->recording.frames);
  } else if (!request.script.isEmpty()) {
    run.feed = scriptedInput(request.script)->frames(run.scene).frames;
    if (run.feed.empty()) {
      exitCode = line.failure(
          Cli::tr("the script '%1' needs a severed vessel, a curved needle and two forceps")
              .arg(request.script));
      return std::nullopt;
    }
  } else {
    // idle hands, one frame a step
    const double dt = 1.0 / run.scene.step.rateHz;
    run.feed.resize(static_cast<std::size_t>(request.frames >= 0 ? request.frames : 100));
    for (std::size_t k = 0; k < run.feed.size(); ++k) run.feed[k].time = static_cast<double>(k) * dt;
  }
  if (request.frames >= 0 && static_cast<std::size_t>(request.frames) < run.feed.size())
    run.feed.resize(static_cast<std::size_t>(request.frames));
  return run;
}

// --record opens before the first step, so that a bad path fails at once; the recording
// names the scene it is made on, and its metadata the script that made it
bool openRecord(const CommandLine& line, const RunRequest& request, const QString& sceneFile,
                sim::RecordingWriter& writer) {
  if (request.record.isEmpty()) return true;
  const std::string meta = request.script.isEmpty()
                               ? std::string()
                               : nlohmann::json{{"script", request.script.toStdString()}}.dump();
  const sim::RecordingStatus s =
      writer.open(request.record.toStdString(), sim::recordScene(sceneFile.toStdString()), meta);
  if (!s.ok()) line.failure(request.record + QStringLiteral(": ") + recordingErrorText(s.error));
  return s.ok();
}

// steps `scene` once per frame, recording each frame when `writer` is open
bool stepEveryFrame(const CommandLine& line, const RunRequest& request, const std::vector<sim::InputFrame>& feed,
                    sim::Scene& scene, sim::RecordingWriter& writer, StepTimeLog& times) {
  const auto cannotRecord = [&] {
    line.failure(request.record + QStringLiteral(": ") + recordingErrorText(sim::RecordingError::CannotWrite));
    return false;
  };
  for (const sim::InputFrame& f : feed) {
    times.add(scene.step(f).times);
    if (writer.isOpen() && !writer.append(f).ok()) return cannotRecord();
  }
  if (writer.isOpen() && !writer.finish().ok()) return cannotRecord();
  return true;
}

// load → run → report
int runScene(const CommandLine& line, const RunOptions& options) {
  const std::optional<RunRequest> request = readRunRequest(line, options);
  if (!request) return kExitUsage;

  // load
  int loadExit = kExitFailure;
  std::optional<RunInput> input = loadRunInput(line, *request, loadExit);
  if (!input) return loadExit;
  sim::RecordingWriter writer;
  if (!openRecord(line, *request, input->sceneFile, writer)) return kExitFailure;

  // run
  sim::Scene scene(std::move(input->scene),
                   request->realtime ? sim::StepMode::RealTime : sim::StepMode::Deterministic);
  StepTimeLog times;
  if (!stepEveryFrame(line, *request, input->feed, scene, writer, times)) return kExitFailure;

  // report
  printRunReport(line.io().out, scene, input->sceneFile, times);
  if (request->json.isEmpty()) return kExitOk;
  return writeCommandOutput(line, request->json,
                            QByteArray::fromStdString(runReportJson(scene, input->sceneFile, times)));
}

}  // namespace

int runRun(const QStringList& args, Streams& io) { return runCommand(QStringLiteral("run"), args, io, &runScene); }

}  // namespace microsim::cli
