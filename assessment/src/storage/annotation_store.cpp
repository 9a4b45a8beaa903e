#include "microsim/assessment/storage/annotation_store.h"

#include "storage/sql_util.h"
#include "storage/viewer_access.h"

#include <QSqlError>
#include <QSqlQuery>

namespace microsim::assessment {

std::optional<qint64> AnnotationStore::add(const Viewer& viewer, qint64 attemptId, const QString& note) {
  if (!requireOpen()) return std::nullopt;
  const QSqlDatabase db = db_.connection();
  if (const HistoryError e = access::mayView(db, viewer, std::nullopt); e != HistoryError::None)
    return fail(e), std::nullopt;
  if (viewer.role != Role::Instructor) return fail(HistoryError::Forbidden), std::nullopt;
  if (note.trimmed().isEmpty()) return fail(HistoryError::InvalidInput), std::nullopt;
  QSqlQuery q(db);
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

std::optional<QList<Annotation>> AnnotationStore::list(const Viewer& viewer, qint64 attemptId) {
  if (!requireOpen()) return std::nullopt;
  const QSqlDatabase db = db_.connection();
  if (const HistoryStatus s = access::mayViewAttempt(db, viewer, attemptId); !s.ok())
    return fail(s.error, s.driverMessage), std::nullopt;
  QSqlQuery q(db);
  q.prepare(QStringLiteral(
      "SELECT n.id, n.author_id, t.name, n.note, n.created_at FROM annotations n "
      "JOIN trainees t ON t.id = n.author_id WHERE n.attempt_id = ? ORDER BY n.created_at, n.id"));
  q.addBindValue(attemptId);
  if (!q.exec()) return fail(HistoryError::QueryFailed, q.lastError().text()), std::nullopt;
  QList<Annotation> out;
  while (q.next())
    out << Annotation{q.value(0).toLongLong(), attemptId, q.value(1).toLongLong(),
                      q.value(2).toString(), q.value(3).toString(), sql::time(q.value(4))};
  succeed();
  return out;
}

}  // namespace microsim::assessment
