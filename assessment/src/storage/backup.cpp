// HistoryDatabase: backup and restore of an SQLite history, and CSV export.
#include "microsim/assessment/storage/csv.h"
#include "microsim/assessment/storage/history_database.h"

#include "storage/sql_util.h"

#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QLocale>
#include <QSaveFile>
#include <QSqlError>
#include <QSqlQuery>

namespace microsim::assessment {

namespace {

enum class BackupCheck { Ok, NotABackup, TooNew };

// opens `file` read-only on its own connection: a microsim history whose schema this
// program knows, and whose pages are sound
BackupCheck checkBackup(const QString& file, QString* message) {
  if (!QFileInfo(file).isFile()) return BackupCheck::NotABackup;
  const QString name = QStringLiteral("microsim-restore-check");
  BackupCheck result = BackupCheck::NotABackup;
  {
    QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), name);
    db.setDatabaseName(file);
    db.setConnectOptions(QStringLiteral("QSQLITE_OPEN_READONLY"));
    if (db.open()) {
      QSqlQuery q(db);
      const bool sound = q.exec(QStringLiteral("PRAGMA quick_check")) && q.next() &&
                         q.value(0).toString() == QLatin1String("ok");
      q.finish();
      const bool ours =
          sound && q.exec(QStringLiteral(
                       "SELECT count(*) FROM sqlite_master WHERE type = 'table' AND name IN "
                       "('schema_migrations', 'trainees', 'attempts')")) &&
          q.next() && q.value(0).toInt() == 3;
      q.finish();
      if (ours && q.exec(QStringLiteral("SELECT COALESCE(MAX(version), 0) FROM schema_migrations")) &&
          q.next()) {
        const std::vector<Migration> known = bundledMigrations();
        const int newest = known.empty() ? 0 : known.back().version;
        result = q.value(0).toInt() > newest ? BackupCheck::TooNew : BackupCheck::Ok;
      }
      if (result == BackupCheck::NotABackup) *message = q.lastError().text();
      q.finish();
    } else {
      *message = db.lastError().text();
    }
    db.close();
  }
  QSqlDatabase::removeDatabase(name);
  return result;
}

QString number(double v) { return QString::number(v, 'g', QLocale::FloatingPointShortest); }

}  // namespace

bool HistoryDatabase::backup(const QString& toFile) {
  if (!isOpen()) return fail(HistoryError::NotOpen);
  if (driver_ != Driver::SQLite) return fail(HistoryError::Unsupported);
  const QFileInfo target(toFile);
  if (target.exists()) return fail(HistoryError::FileError, target.absoluteFilePath());
  // VACUUM INTO reads one snapshot: a consistent copy while others write. It goes to a
  // side file renamed when complete, so a full disk or a killed process never leaves a
  // half-written file under the backup's name.
  const QString partial = target.absoluteFilePath() + QStringLiteral(".part");
  QFile::remove(partial);
  QSqlQuery q(connection());
  q.prepare(QStringLiteral("VACUUM INTO ?"));
  q.addBindValue(partial);
  if (!q.exec()) {
    const QString why = q.lastError().text();
    QFile::remove(partial);
    return fail(HistoryError::FileError, why);
  }
  if (!QFile::rename(partial, target.absoluteFilePath())) {
    QFile::remove(partial);
    return fail(HistoryError::FileError, target.absoluteFilePath());
  }
  return succeed();
}

bool HistoryDatabase::restore(const QString& fromFile) {
  if (!isOpen()) return fail(HistoryError::NotOpen);
  if (driver_ != Driver::SQLite) return fail(HistoryError::Unsupported);
  QString message;
  switch (checkBackup(fromFile, &message)) {
    case BackupCheck::NotABackup:
      return fail(HistoryError::NotABackup, message);
    case BackupCheck::TooNew:
      return fail(HistoryError::BackupTooNew);
    case BackupCheck::Ok:
      break;
  }
  QFile source(fromFile);
  if (!source.open(QIODevice::ReadOnly)) return fail(HistoryError::FileError, source.errorString());

  // closing checkpoints and removes our WAL; a stale one must not be replayed onto the copy
  const QString path = path_;
  close();
  QFile::remove(path + QStringLiteral("-wal"));
  QFile::remove(path + QStringLiteral("-shm"));
  QSaveFile target(path);
  bool copied = target.open(QIODevice::WriteOnly);
  while (copied && !source.atEnd()) copied = target.write(source.read(1 << 20)) >= 0;
  copied = copied && target.commit();  // an atomic rename: the old file stays until here
  const QString copyError = target.errorString();

  const DatabaseStatus reopened = open(path);
  if (!copied) return fail(HistoryError::FileError, copyError);
  if (!reopened.ok()) return fail(HistoryError::QueryFailed, reopened.driverMessage);
  return succeed();
}

bool HistoryDatabase::exportCsv(const Viewer& viewer, QIODevice& out) {
  const QList<AttemptSummary> rows = attempts(viewer);
  if (!last_.ok()) return false;
  QHash<qint64, Trainee> people;
  for (const Trainee& t : trainees()) people.insert(t.id, t);

  QString text = csvRecord({QStringLiteral("attempt"), QStringLiteral("trainee"), QStringLiteral("group"),
                            QStringLiteral("lesson"), QStringLiteral("mode"), QStringLiteral("status"),
                            QStringLiteral("started"), QStringLiteral("finished"), QStringLiteral("score"),
                            QStringLiteral("passed"), QStringLiteral("rubric"), QStringLiteral("rubric_version")});
  for (const AttemptSummary& a : rows) {
    const Trainee who = people.value(a.traineeId);
    const bool scored = a.score.has_value();
    text += csvRecord({QString::number(a.id), who.name, who.group, a.lesson, sql::modeText(a.mode),
                       sql::statusText(a.status), a.started.toString(Qt::ISODateWithMs),
                       a.finished.isValid() ? a.finished.toString(Qt::ISODateWithMs) : QString(),
                       scored ? number(*a.score) : QString(),
                       scored ? (a.passed ? QStringLiteral("1") : QStringLiteral("0")) : QString(),
                       a.rubricId, scored ? QString::number(a.rubricVersion) : QString()});
  }
  if (out.write(text.toUtf8()) < 0) return fail(HistoryError::FileError, out.errorString());
  return succeed();
}

}  // namespace microsim::assessment
