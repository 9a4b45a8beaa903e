#include "microsim/assessment/storage/score_store.h"

#include "microsim/assessment/scoring/score.h"

#include "storage/sql_util.h"
#include "storage/viewer_access.h"

#include <QSqlError>
#include <QSqlQuery>

#include <cmath>
#include <map>
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

// one stored value put back in its field; the keys are pierceValues'
void setPierceValue(PierceMetrics& p, const QString& key, double v) {
  const auto index = [v] { return std::isfinite(v) ? static_cast<int>(std::lround(v)) : -1; };
  const auto surface = [v] {
    return std::isfinite(v) ? static_cast<sim::VesselSurface>(std::lround(v))
                            : sim::VesselSurface::NotAVessel;
  };
  if (key == QLatin1String("entry"))
    p.entry = index();
  else if (key == QLatin1String("exit"))
    p.exit = index();
  else if (key == QLatin1String("time_s"))
    p.time = v;
  else if (key == QLatin1String("vessel"))
    p.vessel = index();
  else if (key == QLatin1String("object"))
    p.object = index();
  else if (key == QLatin1String("end"))
    p.end = index();
  else if (key == QLatin1String("entry_surface"))
    p.entrySurface = surface();
  else if (key == QLatin1String("exit_surface"))
    p.exitSurface = surface();
  else if (key == QLatin1String("entry_angle_deg"))
    p.entryAngleDeg = v;
  else if (key == QLatin1String("exit_angle_deg"))
    p.exitAngleDeg = v;
  else if (key == QLatin1String("bite_mm"))
    p.biteMm = v;
  else if (key == QLatin1String("bite_walls"))
    p.biteWalls = v;
  else if (key == QLatin1String("circumference_deg"))
    p.circumferenceDeg = v;
  else if (key == QLatin1String("full_thickness"))
    p.fullThickness = v > 0.5;
  else if (key == QLatin1String("back_wall"))
    p.backWall = v > 0.5;
}

// writes the score's rows inside the caller's transaction; the driver's text on failure
QString insertScore(const QSqlDatabase& db, qint64 attemptId, const AttemptScore& score,
                    const QByteArray& recording) {
  QSqlQuery q(db);
  QStringList neverEvents;
  for (const std::string& key : score.neverEvents) neverEvents << QString::fromStdString(key);
  q.prepare(
      QStringLiteral("INSERT INTO scores (attempt_id, score, passed, rubric_id, rubric_version, "
                     "never_events, truncated, "
                     "end_product_judged) VALUES (?, ?, ?, ?, ?, ?, ?, 1)"));
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

  q.prepare(
      QStringLiteral("INSERT INTO score_end_product (attempt_id, position, kind, stitch, passage, "
                     "event, angle_deg, measured, "
                     "limit_value) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)"));
  for (std::size_t i = 0; i < score.endProduct.size(); ++i) {
    const EndProductError& e = score.endProduct[i];
    q.addBindValue(attemptId);
    q.addBindValue(int(i));
    q.addBindValue(QString::fromLatin1(endProductErrorKey(e.kind)));
    q.addBindValue(sql::index(e.stitch));
    q.addBindValue(sql::index(e.passage));
    q.addBindValue(sql::index(e.event));
    q.addBindValue(sql::real(e.angleDeg));
    q.addBindValue(sql::real(e.measured));
    q.addBindValue(sql::real(e.limit));
    if (!q.exec()) return q.lastError().text();
  }

  if (!recording.isEmpty()) {
    q.prepare(QStringLiteral("INSERT INTO recordings (attempt_id, data) VALUES (?, ?)"));
    q.addBindValue(attemptId);
    q.addBindValue(recording);
    if (!q.exec()) return q.lastError().text();
  }
  return {};
}

// the end-product rows of one attempt; nullopt with the driver's text in `error` on failure
std::optional<StoredEndProduct> readEndProduct(const QSqlDatabase& db, qint64 attemptId,
                                               QString* error) {
  StoredEndProduct out;
  QSqlQuery q(db);
  q.prepare(QStringLiteral("SELECT end_product_judged FROM scores WHERE attempt_id = ?"));
  q.addBindValue(attemptId);
  if (!q.exec()) return *error = q.lastError().text(), std::nullopt;
  out.judged = q.next() && q.value(0).toInt() == 1;
  if (!out.judged) return out;

  q.prepare(
      QStringLiteral("SELECT kind, stitch, passage, event, angle_deg, measured, limit_value FROM "
                     "score_end_product "
                     "WHERE attempt_id = ? ORDER BY position"));
  q.addBindValue(attemptId);
  if (!q.exec()) return *error = q.lastError().text(), std::nullopt;
  while (q.next()) {
    // a kind this build does not know (written by a newer one) is left out
    const std::optional<EndProductErrorKind> kind =
        endProductErrorKindFromKey(q.value(0).toString().toStdString());
    if (!kind) continue;
    EndProductError e;
    e.kind = *kind;
    e.stitch = sql::indexOrNone(q.value(1));
    e.passage = sql::indexOrNone(q.value(2));
    e.event = sql::indexOrNone(q.value(3));
    e.angleDeg = sql::realOrNan(q.value(4));
    e.measured = sql::realOrNan(q.value(5));
    e.limit = sql::realOrNan(q.value(6));
    out.errors << e;
  }
  return out;
}

}  // namespace

std::vector<PierceMetrics> storedPassages(const QList<StoredPierceValue>& values) {
  std::map<int, PierceMetrics> byPierce;
  for (const StoredPierceValue& v : values) setPierceValue(byPierce[v.pierce], v.key, v.value);
  std::vector<PierceMetrics> out;
  out.reserve(byPierce.size());
  for (const auto& [pierce, p] : byPierce) out.push_back(p);
  return out;
}

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
  QString error;
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

  std::optional<StoredEndProduct> endProduct = readEndProduct(db, attemptId, &error);
  if (!endProduct) return fail(HistoryError::QueryFailed, error), std::nullopt;
  out.endProduct = std::move(*endProduct);

  q.prepare(QStringLiteral("SELECT data FROM recordings WHERE attempt_id = ?"));
  q.addBindValue(attemptId);
  if (!q.exec()) return fail(HistoryError::QueryFailed, q.lastError().text()), std::nullopt;
  if (q.next()) out.recording = q.value(0).toByteArray();
  succeed();
  return out;
}

std::optional<StoredEndProduct> ScoreStore::endProduct(const Viewer& viewer, qint64 attemptId) {
  if (!requireOpen()) return std::nullopt;
  const QSqlDatabase db = db_.connection();
  if (const HistoryStatus s = access::mayViewAttempt(db, viewer, attemptId); !s.ok())
    return fail(s.error, s.driverMessage), std::nullopt;
  QString error;
  std::optional<StoredEndProduct> out = readEndProduct(db, attemptId, &error);
  if (!out) return fail(HistoryError::QueryFailed, error), std::nullopt;
  succeed();
  return out;
}

}  // namespace microsim::assessment
