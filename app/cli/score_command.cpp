// `microsim-cli score --recording REC --rubric R [--scene S] [--db FILE] [--trainee NAME]
// [--lesson ID] [--mode learn|test] [--json OUT]`: replays a recording on its scene
// (deterministically), scores it with a rubric and prints the metrics, points and feedback
// keys; with --db the attempt, its score and the recording are stored for the trainee.
#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/history_text.h"
#include "cli/output_file.h"
#include "cli/recording_input.h"
#include "cli/score_report.h"
#include "cli/spring_scene_input.h"
#include "microsim/assessment/scoring/attempt.h"
#include "microsim/assessment/storage/attempt_store.h"
#include "microsim/assessment/storage/history_database.h"
#include "microsim/assessment/storage/people_store.h"
#include "microsim/assessment/storage/score_store.h"

#include <QFile>

#include <optional>
#include <string>

namespace microsim::cli {

namespace {

namespace as = microsim::assessment;

struct ScoreOptions {
  QCommandLineOption recording{QStringLiteral("recording"), Cli::tr("The recording <file> to score."),
                               QStringLiteral("file")};
  QCommandLineOption rubric{QStringLiteral("rubric"), Cli::tr("The rubric <file> that grades it."),
                            QStringLiteral("file")};
  QCommandLineOption scene{QStringLiteral("scene"), Cli::tr("The scene <file> (default: the one the recording names)."),
                           QStringLiteral("file")};
  QCommandLineOption db{QStringLiteral("db"), Cli::tr("Store the attempt in the history database <file or URL>."),
                        QStringLiteral("location")};
  QCommandLineOption trainee{QStringLiteral("trainee"),
                             Cli::tr("The trainee the attempt belongs to (with --db; added when new)."),
                             QStringLiteral("name")};
  QCommandLineOption lesson{QStringLiteral("lesson"),
                            Cli::tr("The lesson stored with the attempt (default: the rubric's id)."),
                            QStringLiteral("id")};
  QCommandLineOption mode{QStringLiteral("mode"),
                          Cli::tr("The attempt's mode stored with --db: learn or test (default test)."),
                          QStringLiteral("mode")};
  QCommandLineOption json{QStringLiteral("json"), Cli::tr("Write the score, metrics and pierces as JSON to <file>."),
                          QStringLiteral("file")};

  QString usage() const {
    return Cli::tr("Usage: microsim-cli score --recording REC --rubric FILE [--scene FILE] "
                   "[--db FILE --trainee NAME [--lesson ID] [--mode learn|test]] [--json OUT]");
  }
  void declare(CommandLine& line) const { line.addOptions({recording, rubric, scene, db, trainee, lesson, mode, json}); }
};

// what the command line asks for, checked
struct ScoreRequest {
  QString recording;
  QString rubric;
  QString scene;    ///< empty: the one the recording names
  QString db;       ///< empty: not stored
  QString trainee;
  QString lesson;   ///< empty: the rubric's id
  as::AttemptMode mode = as::AttemptMode::Test;
  QString json;
};

std::optional<ScoreRequest> readScoreRequest(const CommandLine& line, const ScoreOptions& o) {
  if (!line.isSet(o.recording) || !line.isSet(o.rubric)) {
    line.usageError(Cli::tr("--recording REC and --rubric FILE are required"));
    return std::nullopt;
  }
  if (line.isSet(o.db) != line.isSet(o.trainee)) {
    line.usageError(Cli::tr("--db and --trainee go together"));
    return std::nullopt;
  }
  ScoreRequest r;
  if (line.isSet(o.mode)) {
    const QString m = line.value(o.mode);
    if (m == QLatin1String("learn")) {
      r.mode = as::AttemptMode::Learn;
    } else if (m != QLatin1String("test")) {
      line.usageError(Cli::tr("--mode is learn or test, not '%1'").arg(m));
      return std::nullopt;
    }
  }
  r.recording = line.value(o.recording);
  r.rubric = line.value(o.rubric);
  r.scene = line.value(o.scene);
  r.db = line.value(o.db);
  r.trainee = line.value(o.trainee);
  r.lesson = line.value(o.lesson);
  r.json = line.value(o.json);
  return r;
}

QString rubricErrorText(const as::RubricError& e) {
  using K = as::RubricErrorKind;
  QString what;
  switch (e.kind) {
    case K::FileNotFound: what = Cli::tr("cannot open the rubric file"); break;
    case K::MalformedJson: what = Cli::tr("not valid JSON"); break;
    case K::WrongType: what = Cli::tr("wrong type"); break;
    case K::MissingField: what = Cli::tr("missing field"); break;
    case K::UnknownField: what = Cli::tr("unknown field"); break;
    case K::UnknownMetric: what = Cli::tr("unknown metric"); break;
    case K::InvalidValue: what = Cli::tr("invalid value"); break;
  }
  QString where = QString::fromStdString(e.file);
  if (e.line > 0) where += QStringLiteral(":%1:%2").arg(e.line).arg(e.column);
  QString text = where + QStringLiteral(": ") + what;
  if (!e.field.empty()) text += QLatin1Char(' ') + Cli::tr("(field %1)").arg(QString::fromStdString(e.field));
  return text;
}

// what is scored: the rubric, the recording, and the scene it ran on
struct ScoreInput {
  as::Rubric rubric;
  RecordingInput replay;
  QString scene;
};

// nullopt after printing why: `exitCode` is kExitFailure, or kExitUsage when only --scene can name the scene
std::optional<ScoreInput> loadScoreInput(const CommandLine& line, const ScoreRequest& request, int& exitCode) {
  exitCode = kExitFailure;
  auto rubric = as::loadRubric(request.rubric.toStdString());
  if (auto* e = std::get_if<as::RubricError>(&rubric)) {
    line.failure(rubricErrorText(*e));
    return std::nullopt;
  }
  std::optional<RecordingInput> replay = readRecordingInput(line, request.recording, RecordingUse::Score);
  if (!replay) return std::nullopt;
  const std::optional<QString> scene =
      request.scene.isEmpty() ? sceneOfRecording(line, *replay, exitCode) : request.scene;
  if (!scene) return std::nullopt;
  return ScoreInput{std::get<as::Rubric>(std::move(rubric)), std::move(*replay), *scene};
}

// stores the attempt for the trainee (added when new); the attempt's id, or nullopt after
// printing why
std::optional<qint64> storeAttempt(const CommandLine& line, const ScoreRequest& request, const as::Rubric& rubric,
                                   const as::AttemptScore& score) {
  as::HistoryDatabase db;
  const as::DatabaseStatus opened = db.open(request.db);
  if (!opened.ok()) {
    line.failure(databaseErrorText(opened, request.db));
    return std::nullopt;
  }
  as::PeopleStore people(db);
  std::optional<qint64> trainee;
  for (const as::Trainee& t : people.trainees())
    if (t.name == request.trainee && t.role == as::Role::Trainee) trainee = t.id;
  if (!trainee) trainee = people.addTrainee(request.trainee);
  if (!trainee) {
    line.failure(Cli::tr("cannot store the attempt: %1").arg(historyErrorText(people.lastError())));
    return std::nullopt;
  }
  QFile file(request.recording);
  const QByteArray bytes = file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
  const QString lesson = request.lesson.isEmpty() ? QString::fromStdString(rubric.id) : request.lesson;
  as::AttemptStore attempts(db);
  as::ScoreStore scores(db);
  const std::optional<qint64> attempt = attempts.begin(*trainee, lesson, request.mode);
  if (!attempt || !scores.finish(*attempt, score, bytes)) {
    const as::HistoryStatus why = attempt ? scores.lastError() : attempts.lastError();
    line.failure(Cli::tr("cannot store the attempt: %1").arg(historyErrorText(why)));
    return std::nullopt;
  }
  return attempt;
}

// load → run → report
int scoreRecording(const CommandLine& line, const ScoreOptions& options) {
  const std::optional<ScoreRequest> request = readScoreRequest(line, options);
  if (!request) return kExitUsage;

  // load
  int loadExit = kExitFailure;
  const std::optional<ScoreInput> input = loadScoreInput(line, *request, loadExit);
  if (!input) return loadExit;

  // run: replay and score
  auto replayed = as::replayAttempt(input->scene.toStdString(), input->replay.recording, input->replay.truncated);
  if (auto* e = std::get_if<as::ReplayError>(&replayed))
    return line.failure(e->sceneError ? describeSceneError(*e->sceneError) : input->scene);
  const as::AttemptScore score = as::scoreAttempt(std::get<as::Attempt>(replayed), input->rubric);

  // report: the table, the history, the JSON
  const ScoredFiles files{input->scene, request->recording, static_cast<int>(input->replay.recording.frames.size())};
  printScoreReport(line.io().out, score, input->rubric, files);
  std::optional<qint64> stored;
  if (!request->db.isEmpty()) {
    stored = storeAttempt(line, *request, input->rubric, score);
    if (!stored) return kExitFailure;
    line.io().out << '\n' << Cli::tr("stored as attempt %1").arg(*stored) << '\n';
  }
  if (request->json.isEmpty()) return kExitOk;
  nlohmann::json doc = scoreReportJson(score, input->rubric, files);
  if (stored) doc["attempt_id"] = *stored;
  return writeCommandOutput(line, request->json, QByteArray::fromStdString(doc.dump(1) + "\n"));
}

}  // namespace

int runScore(const QStringList& args, Streams& io) {
  return runCommand(QStringLiteral("score"), args, io, &scoreRecording);
}

}  // namespace microsim::cli
