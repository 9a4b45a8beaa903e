#include "microsim/assessment/storage/score_store.h"

#include "microsim/assessment/scoring/score.h"

#include "storage/sql_util.h"
#include "storage/viewer_access.h"

#include <QSqlError>
#include <QSqlQuery>

#include <utility>
#include <vector>

namespace microsim::assessment {

namespace {

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

bool ScoreStore::finish(qint64 attemptId, const AttemptScore& score, const QByteArray& recording) {
  if (!requireOpen()) return false;
  QSqlDatabase db = db_.connection();
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

std::optional<StoredScore> ScoreStore::load(const Viewer& viewer, qint64 attemptId) {
  if (!requireOpen()) return std::nullopt;
  const QSqlDatabase db = db_.connection();
  if (const HistoryStatus s = access::mayViewAttempt(db, viewer, attemptId); !s.ok())
    return fail(s.error, s.driverMessage), std::nullopt;

  StoredScore out;
  QSqlQuery q(db);
  q.prepare(QStringLiteral(
      "SELECT metric, value, unit, target, tolerance, weight, points, feedback FROM score_metrics "
      "WHERE attempt_id = ? ORDER BY position"));
  q.addBindValue(attemptId);
  if (!q.exec()) return fail(HistoryError::QueryFailed, q.lastError().text()), std::nullopt;
  while (q.next())
    out.metrics << StoredMetric{q.value(0).toString(),   sql::realOrNan(q.value(1)), q.value(2).toString(),
                                q.value(3).toDouble(),   q.value(4).toDouble(),      q.value(5).toDouble(),
                                q.value(6).toDouble(),   q.value(7).toString()};

  q.prepare(QStringLiteral(
      "SELECT pierce, metric, value FROM score_pierces WHERE attempt_id = ? ORDER BY pierce, metric"));
  q.addBindValue(attemptId);
  if (!q.exec()) return fail(HistoryError::QueryFailed, q.lastError().text()), std::nullopt;
  while (q.next())
    out.pierces << StoredPierceValue{q.value(0).toInt(), q.value(1).toString(), sql::realOrNan(q.value(2))};

  q.prepare(QStringLiteral("SELECT never_events FROM scores WHERE attempt_id = ?"));
  q.addBindValue(attemptId);
  if (!q.exec()) return fail(HistoryError::QueryFailed, q.lastError().text()), std::nullopt;
  if (q.next()) out.neverEvents = q.value(0).toString().split(QLatin1Char(' '), Qt::SkipEmptyParts);

  q.prepare(QStringLiteral("SELECT data FROM recordings WHERE attempt_id = ?"));
  q.addBindValue(attemptId);
  if (!q.exec()) return fail(HistoryError::QueryFailed, q.lastError().text()), std::nullopt;
  if (q.next()) out.recording = q.value(0).toByteArray();
  succeed();
  return out;
}

}  // namespace microsim::assessment
