// `microsim-cli score --recording REC --rubric R [--scene S] [--db FILE] [--trainee NAME]
// [--lesson ID] [--mode learn|test] [--json OUT]`: replays a recording on its scene
// (deterministically), scores it with a rubric and prints the metrics, points and feedback
// keys; with --db the attempt, its score and the recording are stored for the trainee.
#include "cli/commands.h"
#include "cli/output_file.h"

#include "cli/recording_text.h"
#include "cli/spring_scene_input.h"
#include "microsim/assessment/scoring/attempt.h"
#include "microsim/assessment/scoring/rubric.h"
#include "microsim/assessment/scoring/score.h"
#include "microsim/assessment/storage/attempt_store.h"
#include "microsim/assessment/storage/history_database.h"
#include "microsim/assessment/storage/people_store.h"
#include "microsim/assessment/storage/score_store.h"
#include "microsim/sim/scene/recording.h"

#include <QCommandLineParser>
#include <QDir>
#include <QFile>
#include <QFileInfo>

#include <nlohmann/json.hpp>

#include <cmath>
#include <optional>
#include <string>

namespace microsim::cli {

namespace {

namespace as = microsim::assessment;

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

const char* surfaceKey(sim::VesselSurface s) {
  using S = sim::VesselSurface;
  switch (s) {
    case S::Outer: return "outer";
    case S::Inner: return "inner";
    case S::CutEnd: return "cut-end";
    case S::ClampedEnd: return "clamped-end";
    case S::NotAVessel: return "none";
  }
  return "";
}

QString number(double v, int decimals) {
  return std::isfinite(v) ? QString::number(v, 'f', decimals) : QStringLiteral("–");
}

// JSON has no NaN: a missing value is null
nlohmann::json jsonNumber(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); }

// the scene the recording's metadata names, as given or beside the recording
std::optional<QString> sceneFromMetadata(const std::string& metadata, const QString& recordingPath) {
  const nlohmann::json meta = nlohmann::json::parse(metadata, nullptr, false);
  if (!meta.is_object() || !meta.contains("scene") || !meta["scene"].is_string()) return std::nullopt;
  const QString named = QString::fromStdString(meta["scene"].get<std::string>());
  if (QFileInfo::exists(named)) return named;
  const QString beside = QFileInfo(recordingPath).dir().filePath(named);
  return QFileInfo::exists(beside) ? beside : named;
}

void printScore(QTextStream& out, const as::AttemptScore& s, const as::Rubric& rubric,
                const QString& scene, const QString& recording, int frames) {
  out << Cli::tr("rubric") << "  " << QString::fromStdString(rubric.id) << ' '
      << Cli::tr("version %1, pass mark %2").arg(rubric.version).arg(rubric.passMark) << '\n'
      << Cli::tr("scene") << "  " << scene << '\n'
      << Cli::tr("recording") << "  " << recording << "  "
      << Cli::tr("%n frame(s)", nullptr, frames);
  if (s.truncated) out << "  " << Cli::tr("(unfinished: scored as far as it goes)");
  out << "\n\n"
      << Cli::tr("score") << "  " << QString::number(s.score, 'f', 1) << "  "
      << (s.passed ? Cli::tr("passed") : Cli::tr("not passed")) << '\n';
  for (const std::string& n : s.neverEvents) out << "  " << Cli::tr("never-event") << "  " << QString::fromStdString(n) << '\n';

  out << '\n' << Cli::tr("metric").leftJustified(22) << Cli::tr("value").rightJustified(11)
      << "  " << Cli::tr("unit").leftJustified(6) << Cli::tr("target").rightJustified(9)
      << Cli::tr("weight").rightJustified(8) << Cli::tr("points").rightJustified(8) << "  "
      << Cli::tr("feedback") << '\n';
  for (const as::MetricScore& m : s.metrics)
    out << QString::fromStdString(m.key).leftJustified(22) << number(m.value, 3).rightJustified(11)
        << "  " << QString::fromStdString(m.unit).leftJustified(6) << number(m.target, 2).rightJustified(9)
        << number(m.weight, 1).rightJustified(8) << number(m.points, 2).rightJustified(8) << "  "
        << QString::fromStdString(m.feedback) << '\n';

  out << '\n' << Cli::tr("pierces") << '\n';
  if (s.pierces.empty()) out << "  " << Cli::tr("none") << '\n';
  for (std::size_t i = 0; i < s.pierces.size(); ++i) {
    const as::PierceMetrics& p = s.pierces[i];
    out << "  " << QString::number(i + 1).rightJustified(2) << "  "
        << Cli::tr("%1 s, end %2, %3 → %4, entry %5°, exit %6°, bite %7 mm, at %8°")
               .arg(number(p.time, 2))
               .arg(p.end)
               .arg(QLatin1String(surfaceKey(p.entrySurface)), QLatin1String(surfaceKey(p.exitSurface)))
               .arg(number(p.entryAngleDeg, 1), number(p.exitAngleDeg, 1), number(p.biteMm, 3),
                    number(p.circumferenceDeg, 1));
    if (p.fullThickness) out << ", " << Cli::tr("full thickness");
    if (p.backWall) out << ", " << Cli::tr("back wall");
    out << '\n';
  }
}

nlohmann::json scoreJson(const as::AttemptScore& s, const as::Rubric& rubric, const std::string& scene,
                         const std::string& recording, int frames) {
  nlohmann::json doc;
  doc["score"] = s.score;
  doc["passed"] = s.passed;
  doc["rubric"] = {{"id", rubric.id}, {"version", rubric.version}, {"pass_mark", rubric.passMark}};
  doc["scene"] = scene;
  doc["recording"] = recording;
  doc["frames"] = frames;
  doc["truncated"] = s.truncated;
  doc["never_events"] = s.neverEvents;
  nlohmann::json metrics = nlohmann::json::array();
  for (const as::MetricScore& m : s.metrics)
    metrics.push_back({{"key", m.key}, {"value", jsonNumber(m.value)}, {"unit", m.unit},
                       {"target", m.target}, {"tolerance", m.tolerance}, {"weight", m.weight},
                       {"points", m.points}, {"feedback", m.feedback}});
  doc["metrics"] = std::move(metrics);
  nlohmann::json pierces = nlohmann::json::array();
  for (const as::PierceMetrics& p : s.pierces)
    pierces.push_back({{"time", p.time}, {"vessel", p.vessel}, {"end", p.end},
                       {"entry_surface", surfaceKey(p.entrySurface)},
                       {"exit_surface", surfaceKey(p.exitSurface)},
                       {"entry_angle_deg", jsonNumber(p.entryAngleDeg)},
                       {"exit_angle_deg", jsonNumber(p.exitAngleDeg)},
                       {"bite_mm", jsonNumber(p.biteMm)}, {"bite_walls", jsonNumber(p.biteWalls)},
                       {"circumference_deg", jsonNumber(p.circumferenceDeg)},
                       {"full_thickness", p.fullThickness}, {"back_wall", p.backWall}});
  doc["pierces"] = std::move(pierces);
  nlohmann::json stitches = nlohmann::json::array();
  for (const as::StitchMetrics& st : s.stitches)
    stitches.push_back({{"time", st.time}, {"bite_a_mm", st.biteAMm}, {"bite_b_mm", st.biteBMm},
                        {"symmetry_mm", st.symmetryMm}, {"position_deg", jsonNumber(st.positionDeg)},
                        {"spacing_deg", jsonNumber(st.spacingDeg)}, {"full_thickness", st.fullThickness}});
  doc["stitches"] = std::move(stitches);
  return doc;
}

QString historyErrorText(const as::HistoryStatus& s) {
  using E = as::HistoryError;
  QString what;
  switch (s.error) {
    case E::None: break;
    case E::NotOpen: what = Cli::tr("the database is not open"); break;
    case E::Forbidden: what = Cli::tr("not allowed"); break;
    case E::NotFound: what = Cli::tr("not found"); break;
    case E::NotInProgress: what = Cli::tr("the attempt is no longer in progress"); break;
    case E::NameTaken: what = Cli::tr("the name is taken"); break;
    case E::InvalidInput: what = Cli::tr("invalid input"); break;
    default: what = Cli::tr("database error"); break;
  }
  if (!s.driverMessage.isEmpty()) what += QStringLiteral(" (") + s.driverMessage + QLatin1Char(')');
  return what;
}

// stores the attempt for the trainee (added when new); the attempt's id, or nullopt after
// printing why
std::optional<qint64> store(const QString& location, const QString& traineeName, const QString& lesson,
                            as::AttemptMode mode, const as::AttemptScore& score,
                            const QString& recordingPath, const QString& prefix, Streams& io) {
  as::HistoryDatabase db;
  const as::DatabaseStatus opened = db.open(location);
  if (!opened.ok()) {
    io.err << prefix << Cli::tr("cannot open the history database %1").arg(location);
    if (!opened.driverMessage.isEmpty()) io.err << " (" << opened.driverMessage << ')';
    io.err << '\n';
    return std::nullopt;
  }
  as::PeopleStore people(db);
  std::optional<qint64> trainee;
  for (const as::Trainee& t : people.trainees())
    if (t.name == traineeName && t.role == as::Role::Trainee) trainee = t.id;
  if (!trainee) trainee = people.addTrainee(traineeName);
  if (!trainee) {
    io.err << prefix << Cli::tr("cannot store the attempt: %1").arg(historyErrorText(people.lastError())) << '\n';
    return std::nullopt;
  }
  QFile file(recordingPath);
  const QByteArray bytes = file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
  as::AttemptStore attempts(db);
  as::ScoreStore scores(db);
  const std::optional<qint64> attempt = attempts.begin(*trainee, lesson, mode);
  if (!attempt || !scores.finish(*attempt, score, bytes)) {
    const as::HistoryStatus why = attempt ? scores.lastError() : attempts.lastError();
    io.err << prefix << Cli::tr("cannot store the attempt: %1").arg(historyErrorText(why)) << '\n';
    return std::nullopt;
  }
  return attempt;
}

}  // namespace

int runScore(const QStringList& args, Streams& io) {
  QCommandLineParser parser;
  const QCommandLineOption recordingOpt(QStringLiteral("recording"), Cli::tr("The recording <file> to score."),
                                        QStringLiteral("file"));
  const QCommandLineOption rubricOpt(QStringLiteral("rubric"), Cli::tr("The rubric <file> that grades it."),
                                     QStringLiteral("file"));
  const QCommandLineOption sceneOpt(QStringLiteral("scene"),
                                    Cli::tr("The scene <file> (default: the one the recording names)."),
                                    QStringLiteral("file"));
  const QCommandLineOption dbOpt(QStringLiteral("db"),
                                 Cli::tr("Store the attempt in the history database <file or URL>."),
                                 QStringLiteral("location"));
  const QCommandLineOption traineeOpt(QStringLiteral("trainee"),
                                      Cli::tr("The trainee the attempt belongs to (with --db; added when new)."),
                                      QStringLiteral("name"));
  const QCommandLineOption lessonOpt(QStringLiteral("lesson"),
                                     Cli::tr("The lesson stored with the attempt (default: the rubric's id)."),
                                     QStringLiteral("id"));
  const QCommandLineOption modeOpt(QStringLiteral("mode"),
                                   Cli::tr("The attempt's mode stored with --db: learn or test (default test)."),
                                   QStringLiteral("mode"));
  const QCommandLineOption jsonOpt(QStringLiteral("json"),
                                   Cli::tr("Write the score, metrics and pierces as JSON to <file>."),
                                   QStringLiteral("file"));
  const QCommandLineOption help(QStringList{QStringLiteral("h"), QStringLiteral("help")}, Cli::tr("Show this help."));
  parser.addOptions({recordingOpt, rubricOpt, sceneOpt, dbOpt, traineeOpt, lessonOpt, modeOpt, jsonOpt, help});
  const QString prefix = QStringLiteral("microsim-cli score: ");
  if (!parser.parse(QStringList{QStringLiteral("score")} + args)) {
    io.err << prefix << parser.errorText() << '\n';
    return kExitUsage;
  }
  if (parser.isSet(help)) {
    io.out << Cli::tr("Usage: microsim-cli score --recording REC --rubric FILE [--scene FILE] "
                      "[--db FILE --trainee NAME [--lesson ID] [--mode learn|test]] [--json OUT]")
           << "\n\n"
           << parser.helpText().section(QLatin1Char('\n'), 2);
    return kExitOk;
  }
  if (!parser.positionalArguments().isEmpty()) {
    io.err << prefix << Cli::tr("unexpected argument '%1'").arg(parser.positionalArguments().front()) << '\n';
    return kExitUsage;
  }
  if (!parser.isSet(recordingOpt) || !parser.isSet(rubricOpt)) {
    io.err << prefix << Cli::tr("--recording REC and --rubric FILE are required") << '\n';
    return kExitUsage;
  }
  if (parser.isSet(dbOpt) != parser.isSet(traineeOpt)) {
    io.err << prefix << Cli::tr("--db and --trainee go together") << '\n';
    return kExitUsage;
  }
  as::AttemptMode mode = as::AttemptMode::Test;
  if (parser.isSet(modeOpt)) {
    const QString m = parser.value(modeOpt);
    if (m == QLatin1String("learn"))
      mode = as::AttemptMode::Learn;
    else if (m != QLatin1String("test")) {
      io.err << prefix << Cli::tr("--mode is learn or test, not '%1'").arg(m) << '\n';
      return kExitUsage;
    }
  }

  // the rubric, the recording, the scene it ran on
  auto loaded = as::loadRubric(parser.value(rubricOpt).toStdString());
  if (auto* e = std::get_if<as::RubricError>(&loaded)) {
    io.err << prefix << rubricErrorText(*e) << '\n';
    return kExitFailure;
  }
  const as::Rubric rubric = std::get<as::Rubric>(std::move(loaded));
  const QString recordingPath = parser.value(recordingOpt);
  sim::Recording recording;
  const sim::RecordingStatus status = sim::readRecording(recordingPath.toStdString(), recording);
  const bool truncated = status.error == sim::RecordingError::Truncated;
  if (truncated) {
    io.err << prefix << recordingPath << ": " << recordingErrorText(status.error) << "; "
           << Cli::tr("scoring its %n complete frame(s)", nullptr, static_cast<int>(recording.frames.size()))
           << '\n';
  } else if (!status.ok()) {
    io.err << prefix << recordingPath << ": " << recordingErrorText(status.error) << ' '
           << Cli::tr("(at byte %1)").arg(status.offset) << '\n';
    return kExitFailure;
  }
  std::optional<QString> scene;
  if (parser.isSet(sceneOpt))
    scene = parser.value(sceneOpt);
  else
    scene = sceneFromMetadata(recording.metadata, recordingPath);
  if (!scene) {
    io.err << prefix << Cli::tr("the recording names no scene: give --scene FILE") << '\n';
    return kExitUsage;
  }

  // replay and score
  auto replayed = as::replayAttempt(scene->toStdString(), recording, truncated);
  if (auto* e = std::get_if<as::ReplayError>(&replayed)) {
    io.err << prefix << (e->sceneError ? describeSceneError(*e->sceneError) : *scene) << '\n';
    return kExitFailure;
  }
  const as::AttemptScore score = as::scoreAttempt(std::get<as::Attempt>(replayed), rubric);
  const int frames = static_cast<int>(recording.frames.size());
  printScore(io.out, score, rubric, *scene, recordingPath, frames);

  std::optional<qint64> stored;
  if (parser.isSet(dbOpt)) {
    const QString lesson = parser.isSet(lessonOpt) ? parser.value(lessonOpt) : QString::fromStdString(rubric.id);
    stored = store(parser.value(dbOpt), parser.value(traineeOpt), lesson, mode, score, recordingPath, prefix, io);
    if (!stored) return kExitFailure;
    io.out << '\n' << Cli::tr("stored as attempt %1").arg(*stored) << '\n';
  }

  if (parser.isSet(jsonOpt)) {
    nlohmann::json doc = scoreJson(score, rubric, scene->toStdString(), recordingPath.toStdString(), frames);
    if (stored) doc["attempt_id"] = *stored;
    QString why;
    if (!writeOutputFile(parser.value(jsonOpt), QByteArray::fromStdString(doc.dump(1) + "\n"), why)) {
      io.err << prefix << Cli::tr("cannot write %1: %2").arg(parser.value(jsonOpt), why) << '\n';
      return kExitFailure;
    }
  }
  return kExitOk;
}

}  // namespace microsim::cli
