#include "microsim/assessment/storage/attempt_store.h"

#include "storage/sql_util.h"
#include "storage/viewer_access.h"

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

}  // namespace

std::optional<qint64> AttemptStore::begin(qint64 traineeId, const QString& lesson, AttemptMode mode) {
  if (!requireOpen()) return std::nullopt;
  const QSqlDatabase db = db_.connection();
  if (!access::storedRole(db, traineeId)) return fail(HistoryError::NotFound), std::nullopt;
  QSqlQuery q(db);
  q.prepare(QStringLiteral(
      "INSERT INTO attempts (trainee_id, lesson, mode, status, started_at, session) "
      "VALUES (?, ?, ?, 'in_progress', ?, ?) RETURNING id"));
  q.addBindValue(traineeId);
  q.addBindValue(sql::text(lesson));
  q.addBindValue(sql::modeText(mode));
  q.addBindValue(sql::now());
  q.addBindValue(db_.session());
  if (!q.exec() || !q.next()) return fail(HistoryError::QueryFailed, q.lastError().text()), std::nullopt;
  succeed();
  return q.value(0).toLongLong();
}

bool AttemptStore::abandon(qint64 attemptId) {
  if (!requireOpen()) return false;
  QSqlQuery q(db_.connection());
  q.prepare(QStringLiteral(
      "UPDATE attempts SET status = 'abandoned', finished_at = ? WHERE id = ? AND status = 'in_progress'"));
  q.addBindValue(sql::now());
  q.addBindValue(attemptId);
  if (!q.exec()) return fail(HistoryError::QueryFailed, q.lastError().text());
  if (q.numRowsAffected() == 1) return succeed();
  // nothing changed: no such attempt, or it ended already
  q.prepare(QStringLiteral("SELECT count(*) FROM attempts WHERE id = ?"));
  q.addBindValue(attemptId);
  if (!q.exec() || !q.next()) return fail(HistoryError::QueryFailed, q.lastError().text());
  return fail(q.value(0).toInt() == 0 ? HistoryError::NotFound : HistoryError::NotInProgress);
}

QList<AttemptSummary> AttemptStore::list(const Viewer& viewer, std::optional<qint64> traineeId) {
  QList<AttemptSummary> out;
  if (!requireOpen()) return out;
  const QSqlDatabase db = db_.connection();
  if (const HistoryError e = access::mayView(db, viewer, traineeId); e != HistoryError::None) return fail(e), out;
  if (viewer.role == Role::Trainee) traineeId = viewer.userId;
  QSqlQuery q(db);
  q.prepare(QString::fromLatin1(kSummaryColumns) +
            (traineeId ? QStringLiteral("WHERE a.trainee_id = ? ") : QString()) +
            QStringLiteral("ORDER BY a.started_at, a.id"));
  if (traineeId) q.addBindValue(*traineeId);
  if (!q.exec()) return fail(HistoryError::QueryFailed, q.lastError().text()), out;
  while (q.next()) out << readSummary(q);
  succeed();
  return out;
}

std::optional<AttemptSummary> AttemptStore::summary(const Viewer& viewer, qint64 attemptId) {
  if (!requireOpen()) return std::nullopt;
  const QSqlDatabase db = db_.connection();
  if (const HistoryStatus s = access::mayViewAttempt(db, viewer, attemptId); !s.ok())
    return fail(s.error, s.driverMessage), std::nullopt;
  QSqlQuery q(db);
  q.prepare(QString::fromLatin1(kSummaryColumns) + QStringLiteral("WHERE a.id = ?"));
  q.addBindValue(attemptId);
  if (!q.exec()) return fail(HistoryError::QueryFailed, q.lastError().text()), std::nullopt;
  if (!q.next()) return fail(HistoryError::NotFound), std::nullopt;
  succeed();
  return readSummary(q);
}

int AttemptStore::interruptEndedSessions() {
  if (!requireOpen()) return 0;
  const QSqlDatabase db = db_.connection();
  QSqlQuery q(db);
  if (!q.exec(QStringLiteral("SELECT id, session FROM attempts WHERE status = 'in_progress'")))
    return fail(HistoryError::QueryFailed, q.lastError().text()), 0;
  std::vector<std::pair<qint64, QString>> open;
  while (q.next()) open.emplace_back(q.value(0).toLongLong(), q.value(1).toString());
  q.finish();
  int interrupted = 0;
  for (const auto& [id, session] : open) {
    if (!db_.sessionEnded(session)) continue;
    QSqlQuery u(db);
    u.prepare(QStringLiteral(
        "UPDATE attempts SET status = 'interrupted', finished_at = ? WHERE id = ? AND status = 'in_progress'"));
    u.addBindValue(sql::now());
    u.addBindValue(id);
    if (u.exec()) interrupted += u.numRowsAffected() == 1 ? 1 : 0;
  }
  succeed();
  return interrupted;
}

}  // namespace microsim::assessment
