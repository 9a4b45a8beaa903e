// HistoryDatabase: attempts, their stored scores, and instructors' annotations.
#include "microsim/assessment/storage/history_database.h"
#include "microsim/assessment/scoring/score.h"

#include "storage/sql_util.h"

#include <QSqlError>
#include <QSqlQuery>

#include <utility>
#include <vector>

namespace microsim::assessment {

namespace {

constexpr const char* kSummaryColumns =
    "SELECT a.id, a.trainee_id, a.lesson, a.mode, a.status, a.started_at, a.finished_at, "
    "s.score, s.passed, s.rubric_id, s.rubric_version FROM attempts a "
    "LEFT JOIN scores s ON s.attempt_id = a.id ";

AttemptSummary readSummary(const QSqlQuery& q) {
  AttemptSummary a;
  a.id = q.value(0).toLongLong();
  a.traineeId = q.value(1).toLongLong();
  a.lesson = q.value(2).toString();
  a.mode = sql::modeFromText(q.value(3).toString());
  a.status = sql::statusFromText(q.value(4).toString());
  a.started = sql::time(q.value(5));
  a.finished = sql::time(q.value(6));
  if (!q.value(7).isNull()) a.score = q.value(7).toDouble();
  a.passed = q.value(8).toInt() == 1;
  a.rubricId = q.value(9).toString();
  a.rubricVersion = q.value(10).toInt();
  return a;
}

// one pierce as (key, value) rows; NaN values are stored as NULL
std::vector<std::pair<const char*, double>> pierceValues(const PierceMetrics& p) {
  return {{"entry", p.entry},
          {"exit", p.exit},
          {"time_s", p.time},
          {"vessel", p.vessel},
          {"object", p.object},
          {"end", p.end},
          {"entry_surface", double(p.entrySurface)},
          {"exit_surface", double(p.exitSurface)},
          {"entry_angle_deg", p.entryAngleDeg},
          {"exit_angle_deg", p.exitAngleDeg},
          {"bite_mm", p.biteMm},
          {"bite_walls", p.biteWalls},
          {"circumference_deg", p.circumferenceDeg},
          {"full_thickness", p.fullThickness ? 1.0 : 0.0},
          {"back_wall", p.backWall ? 1.0 : 0.0}};
}

// writes the score's rows inside the caller's transaction; the driver's text on failure
QString insertScore(const QSqlDatabase& db, qint64 attemptId, const AttemptScore& score,
                    const QByteArray& recording) {
  QSqlQuery q(db);
  QStringList neverEvents;
  for (const std::string& key : score.neverEvents) neverEvents << QString::fromStdString(key);
  q.prepare(QStringLiteral(
      "INSERT INTO scores (attempt_id, score, passed, rubric_id, rubric_version, never_events, truncated) "
      "VALUES (?, ?, ?, ?, ?, ?, ?)"));
  q.addBindValue(attemptId);
  q.addBindValue(score.score);
  q.addBindValue(score.passed ? 1 : 0);
  q.addBindValue(sql::text(score.rubricId));
  q.addBindValue(score.rubricVersion);
  q.addBindValue(sql::text(neverEvents.join(QLatin1Char(' '))));
  q.addBindValue(score.truncated ? 1 : 0);
  if (!q.exec()) return q.lastError().text();

  q.prepare(QStringLiteral(
      "INSERT INTO score_metrics (attempt_id, position, metric, value, unit, target, tolerance, weight, "
      "points, feedback) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?)"));
  for (std::size_t i = 0; i < score.metrics.size(); ++i) {
    const MetricScore& m = score.metrics[i];
    q.addBindValue(attemptId);
    q.addBindValue(int(i));
    q.addBindValue(sql::text(m.key));
    q.addBindValue(sql::real(m.value));
    q.addBindValue(sql::text(m.unit));
    q.addBindValue(m.target);
    q.addBindValue(m.tolerance);
    q.addBindValue(m.weight);
    q.addBindValue(m.points);
    q.addBindValue(sql::text(m.feedback));
    if (!q.exec()) return q.lastError().text();
  }

  q.prepare(QStringLiteral("INSERT INTO score_pierces (attempt_id, pierce, metric, value) VALUES (?, ?, ?, ?)"));
  for (std::size_t i = 0; i < score.pierces.size(); ++i) {
    for (const auto& [key, value] : pierceValues(score.pierces[i])) {
      q.addBindValue(attemptId);
      q.addBindValue(int(i));
      q.addBindValue(QString::fromLatin1(key));
      q.addBindValue(sql::real(value));
      if (!q.exec()) return q.lastError().text();
    }
  }

  if (!recording.isEmpty()) {
    q.prepare(QStringLiteral("INSERT INTO recordings (attempt_id, data) VALUES (?, ?)"));
    q.addBindValue(attemptId);
    q.addBindValue(recording);
    if (!q.exec()) return q.lastError().text();
  }
  return {};
}

}  // namespace

std::optional<qint64> HistoryDatabase::beginAttempt(qint64 traineeId, const QString& lesson,
                                                    AttemptMode mode) {
  if (!isOpen()) return fail(HistoryError::NotOpen), std::nullopt;
  if (!storedRole(traineeId)) return fail(HistoryError::NotFound), std::nullopt;
  QSqlQuery q(connection());
  q.prepare(QStringLiteral(
      "INSERT INTO attempts (trainee_id, lesson, mode, status, started_at, session) "
      "VALUES (?, ?, ?, 'in_progress', ?, ?) RETURNING id"));
  q.addBindValue(traineeId);
  q.addBindValue(sql::text(lesson));
  q.addBindValue(sql::modeText(mode));
  q.addBindValue(sql::now());
  q.addBindValue(session_);
  if (!q.exec() || !q.next()) return fail(HistoryError::QueryFailed, q.lastError().text()), std::nullopt;
  succeed();
  return q.value(0).toLongLong();
}

bool HistoryDatabase::finishAttempt(qint64 attemptId, const AttemptScore& score,
                                    const QByteArray& recording) {
  if (!isOpen()) return fail(HistoryError::NotOpen);
  QSqlDatabase db = connection();
  if (!db.transaction()) return fail(HistoryError::QueryFailed, db.lastError().text());
  const auto abort = [&](HistoryError error, const QString& message = {}) {
    db.rollback();
    return fail(error, message);
  };

  QSqlQuery q(db);
  q.prepare(QStringLiteral("SELECT status FROM attempts WHERE id = ?"));
  q.addBindValue(attemptId);
  if (!q.exec()) return abort(HistoryError::QueryFailed, q.lastError().text());
  if (!q.next()) return abort(HistoryError::NotFound);
  if (sql::statusFromText(q.value(0).toString()) != AttemptStatus::InProgress)
    return abort(HistoryError::NotInProgress);
  q.finish();

  const QString error = insertScore(db, attemptId, score, recording);
  if (!error.isEmpty()) return abort(HistoryError::QueryFailed, error);

  // the status change last: the triggers accept score rows only while in progress
  q.prepare(QStringLiteral(
      "UPDATE attempts SET status = 'finished', finished_at = ? WHERE id = ? AND status = 'in_progress'"));
  q.addBindValue(sql::now());
  q.addBindValue(attemptId);
  if (!q.exec()) return abort(HistoryError::QueryFailed, q.lastError().text());
  if (q.numRowsAffected() != 1) return abort(HistoryError::NotInProgress);
  if (!db.commit()) return abort(HistoryError::QueryFailed, db.lastError().text());
  return succeed();
}

QList<AttemptSummary> HistoryDatabase::attempts(const Viewer& viewer, std::optional<qint64> traineeId) {
  QList<AttemptSummary> out;
  if (!mayView(viewer, traineeId)) return out;
  if (viewer.role == Role::Trainee) traineeId = viewer.userId;
  QSqlQuery q(connection());
  q.prepare(QString::fromLatin1(kSummaryColumns) +
            (traineeId ? QStringLiteral("WHERE a.trainee_id = ? ") : QString()) +
            QStringLiteral("ORDER BY a.started_at, a.id"));
  if (traineeId) q.addBindValue(*traineeId);
  if (!q.exec()) return fail(HistoryError::QueryFailed, q.lastError().text()), out;
  while (q.next()) out << readSummary(q);
  succeed();
  return out;
}

std::optional<AttemptDetail> HistoryDatabase::attempt(const Viewer& viewer, qint64 attemptId) {
  if (!mayView(viewer, std::nullopt)) return std::nullopt;
  QSqlDatabase db = connection();
  QSqlQuery q(db);
  q.prepare(QString::fromLatin1(kSummaryColumns) + QStringLiteral("WHERE a.id = ?"));
  q.addBindValue(attemptId);
  if (!q.exec()) return fail(HistoryError::QueryFailed, q.lastError().text()), std::nullopt;
  if (!q.next()) return fail(HistoryError::NotFound), std::nullopt;
  AttemptDetail d;
  d.summary = readSummary(q);
  if (viewer.role == Role::Trainee && d.summary.traineeId != viewer.userId)
    return fail(HistoryError::Forbidden), std::nullopt;

  q.prepare(QStringLiteral(
      "SELECT metric, value, unit, target, tolerance, weight, points, feedback FROM score_metrics "
      "WHERE attempt_id = ? ORDER BY position"));
  q.addBindValue(attemptId);
  if (!q.exec()) return fail(HistoryError::QueryFailed, q.lastError().text()), std::nullopt;
  while (q.next())
    d.metrics << StoredMetric{q.value(0).toString(),   sql::realOrNan(q.value(1)), q.value(2).toString(),
                              q.value(3).toDouble(),   q.value(4).toDouble(),      q.value(5).toDouble(),
                              q.value(6).toDouble(),   q.value(7).toString()};

  q.prepare(QStringLiteral(
      "SELECT pierce, metric, value FROM score_pierces WHERE attempt_id = ? ORDER BY pierce, metric"));
  q.addBindValue(attemptId);
  if (!q.exec()) return fail(HistoryError::QueryFailed, q.lastError().text()), std::nullopt;
  while (q.next())
    d.pierces << StoredPierceValue{q.value(0).toInt(), q.value(1).toString(), sql::realOrNan(q.value(2))};

  q.prepare(QStringLiteral("SELECT never_events FROM scores WHERE attempt_id = ?"));
  q.addBindValue(attemptId);
  if (q.exec() && q.next())
    d.neverEvents = q.value(0).toString().split(QLatin1Char(' '), Qt::SkipEmptyParts);

  q.prepare(QStringLiteral(
      "SELECT n.id, n.author_id, t.name, n.note, n.created_at FROM annotations n "
      "JOIN trainees t ON t.id = n.author_id WHERE n.attempt_id = ? ORDER BY n.created_at, n.id"));
  q.addBindValue(attemptId);
  if (!q.exec()) return fail(HistoryError::QueryFailed, q.lastError().text()), std::nullopt;
  while (q.next())
    d.annotations << Annotation{q.value(0).toLongLong(), attemptId, q.value(1).toLongLong(),
                                q.value(2).toString(), q.value(3).toString(), sql::time(q.value(4))};

  q.prepare(QStringLiteral("SELECT data FROM recordings WHERE attempt_id = ?"));
  q.addBindValue(attemptId);
  if (!q.exec()) return fail(HistoryError::QueryFailed, q.lastError().text()), std::nullopt;
  if (q.next()) d.recording = q.value(0).toByteArray();
  succeed();
  return d;
}

std::optional<qint64> HistoryDatabase::annotate(const Viewer& viewer, qint64 attemptId,
                                                const QString& note) {
  if (!mayView(viewer, std::nullopt)) return std::nullopt;
  if (viewer.role != Role::Instructor) return fail(HistoryError::Forbidden), std::nullopt;
  if (note.trimmed().isEmpty()) return fail(HistoryError::InvalidInput), std::nullopt;
  QSqlQuery q(connection());
  q.prepare(QStringLiteral("SELECT id FROM attempts WHERE id = ?"));
  q.addBindValue(attemptId);
  if (!q.exec()) return fail(HistoryError::QueryFailed, q.lastError().text()), std::nullopt;
  if (!q.next()) return fail(HistoryError::NotFound), std::nullopt;
  q.prepare(QStringLiteral(
      "INSERT INTO annotations (attempt_id, author_id, note, created_at) VALUES (?, ?, ?, ?) RETURNING id"));
  q.addBindValue(attemptId);
  q.addBindValue(viewer.userId);
  q.addBindValue(note);
  q.addBindValue(sql::now());
  if (!q.exec() || !q.next()) return fail(HistoryError::QueryFailed, q.lastError().text()), std::nullopt;
  succeed();
  return q.value(0).toLongLong();
}

}  // namespace microsim::assessment
