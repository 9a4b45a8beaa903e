#include "storage/viewer_access.h"

#include "storage/sql_util.h"

#include <QSqlError>
#include <QSqlQuery>

namespace microsim::assessment::access {

std::optional<Role> storedRole(const QSqlDatabase& db, qint64 personId) {
  QSqlQuery q(db);
  q.prepare(QStringLiteral("SELECT role FROM trainees WHERE id = ?"));
  q.addBindValue(personId);
  if (!q.exec() || !q.next()) return std::nullopt;
  return sql::roleFromText(q.value(0).toString());
}

HistoryError mayView(const QSqlDatabase& db, const Viewer& viewer, std::optional<qint64> traineeId) {
  const std::optional<Role> role = storedRole(db, viewer.userId);
  if (!role || *role != viewer.role) return HistoryError::Forbidden;
  if (viewer.role == Role::Trainee && traineeId && *traineeId != viewer.userId) return HistoryError::Forbidden;
  return HistoryError::None;
}

HistoryStatus mayViewAttempt(const QSqlDatabase& db, const Viewer& viewer, qint64 attemptId) {
  if (const HistoryError e = mayView(db, viewer, std::nullopt); e != HistoryError::None) return {e, {}};
  QSqlQuery q(db);
  q.prepare(QStringLiteral("SELECT trainee_id FROM attempts WHERE id = ?"));
  q.addBindValue(attemptId);
  if (!q.exec()) return {HistoryError::QueryFailed, q.lastError().text()};
  if (!q.next()) return {HistoryError::NotFound, {}};
  if (viewer.role == Role::Trainee && q.value(0).toLongLong() != viewer.userId) return {HistoryError::Forbidden, {}};
  return {};
}

}  // namespace microsim::assessment::access
