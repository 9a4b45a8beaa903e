#include "microsim/assessment/storage/migrations.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QRegularExpression>
#include <QSqlError>
#include <QSqlQuery>

#include <algorithm>

namespace microsim::assessment {

namespace {

const QString kResourceDir = QStringLiteral(":/microsim/migrations");

// rows that break a foreign key, as PRAGMA foreign_key_check lists them; empty when none
QString foreignKeyViolations(const QSqlDatabase& db) {
  QSqlQuery q(db);
  if (!q.exec(QStringLiteral("PRAGMA foreign_key_check"))) return q.lastError().text();
  QStringList rows;
  while (q.next()) rows << QStringLiteral("%1 row %2 -> %3").arg(q.value(0).toString(), q.value(1).toString(), q.value(2).toString());
  return rows.isEmpty() ? QString() : QStringLiteral("foreign key check failed: ") + rows.join(QStringLiteral(", "));
}

// SQLite's foreign key enforcement for the duration of the migrations: off, since a table
// rebuild would otherwise cascade the old table's drop into its children (the pragma is a
// no-op inside a transaction, so it is set around them); put back as it was afterwards
class SqliteForeignKeysOff {
 public:
  explicit SqliteForeignKeysOff(const QSqlDatabase& db) : db_(db) {
    if (driverOf(db_) != Driver::SQLite) return;
    QSqlQuery q(db_);
    wasOn_ = q.exec(QStringLiteral("PRAGMA foreign_keys")) && q.next() && q.value(0).toInt() == 1;
    q.finish();
    if (wasOn_) q.exec(QStringLiteral("PRAGMA foreign_keys = OFF"));
  }
  ~SqliteForeignKeysOff() {
    if (wasOn_) QSqlQuery(db_).exec(QStringLiteral("PRAGMA foreign_keys = ON"));
  }
  SqliteForeignKeysOff(const SqliteForeignKeysOff&) = delete;
  SqliteForeignKeysOff& operator=(const SqliteForeignKeysOff&) = delete;

 private:
  QSqlDatabase db_;
  bool wasOn_ = false;
};

bool ensureMigrationsTable(QSqlDatabase& db) {
  QSqlQuery q(db);
  return q.exec(QStringLiteral(
      "CREATE TABLE IF NOT EXISTS schema_migrations ("
      " version INTEGER PRIMARY KEY, name TEXT NOT NULL, applied_at TEXT NOT NULL)"));
}

}  // namespace

std::vector<Migration> bundledMigrations() {
  std::vector<Migration> out;
  static const QRegularExpression pattern(QStringLiteral("^(\\d{4})_[a-z0-9_]+\\.sql$"));
  const QStringList files = QDir(kResourceDir).entryList(QDir::Files, QDir::Name);
  for (const QString& name : files) {
    const auto match = pattern.match(name);
    if (!match.hasMatch()) continue;
    QFile file(kResourceDir + QLatin1Char('/') + name);
    if (!file.open(QIODevice::ReadOnly)) continue;
    out.push_back({match.captured(1).toInt(), name, QString::fromUtf8(file.readAll())});
  }
  std::sort(out.begin(), out.end(),
            [](const Migration& a, const Migration& b) { return a.version < b.version; });
  return out;
}

QStringList splitStatements(const QString& sql) {
  QStringList statements;
  QString current;
  const QStringList lines = sql.split(QLatin1Char('\n'));
  for (const QString& raw : lines) {
    const QString line = raw.trimmed();
    if (line.isEmpty() || line.startsWith(QLatin1String("--"))) continue;
    current += line + QLatin1Char('\n');
    if (line.endsWith(QLatin1Char(';'))) {
      current.chop(2);  // the ';' and the newline
      statements << current.trimmed();
      current.clear();
    }
  }
  if (!current.trimmed().isEmpty()) statements << current.trimmed();
  return statements;
}

Driver driverOf(const QSqlDatabase& db) {
  return db.driverName() == QLatin1String("QPSQL") ? Driver::PostgreSQL : Driver::SQLite;
}

QStringList statementsFor(const QString& sql, Driver driver) {
  const bool sqlite = driver == Driver::SQLite;
  const QString mine = sqlite ? QStringLiteral("@SQLITE@") : QStringLiteral("@POSTGRESQL@");
  const QString theirs = sqlite ? QStringLiteral("@POSTGRESQL@") : QStringLiteral("@SQLITE@");
  QStringList out;
  for (QString statement : splitStatements(sql)) {
    if (statement.startsWith(theirs)) continue;
    if (statement.startsWith(mine)) statement = statement.mid(mine.size()).trimmed();
    statement.replace(QLatin1String("@ID@"),
                      sqlite ? QLatin1String("INTEGER PRIMARY KEY") : QLatin1String("BIGSERIAL PRIMARY KEY"));
    statement.replace(QLatin1String("@BLOB@"), sqlite ? QLatin1String("BLOB") : QLatin1String("BYTEA"));
    statement.replace(QLatin1String("@REAL@"),
                      sqlite ? QLatin1String("REAL") : QLatin1String("DOUBLE PRECISION"));
    out << statement;
  }
  return out;
}

int schemaVersion(QSqlDatabase& db) {
  if (!ensureMigrationsTable(db)) return -1;
  QSqlQuery q(db);
  if (!q.exec(QStringLiteral("SELECT COALESCE(MAX(version), 0) FROM schema_migrations")) || !q.next())
    return -1;
  return q.value(0).toInt();
}

MigrationOutcome migrate(QSqlDatabase& db, const std::vector<Migration>& migrations) {
  MigrationOutcome outcome;
  if (!ensureMigrationsTable(db)) {
    outcome.result = MigrationResult::Failed;
    outcome.driverMessage = db.lastError().text();
    return outcome;
  }
  outcome.version = schemaVersion(db);
  const int newest = migrations.empty() ? 0 : migrations.back().version;
  if (outcome.version > newest) {
    outcome.result = MigrationResult::NewerSchema;
    return outcome;
  }

  const SqliteForeignKeysOff foreignKeysOff(db);
  for (const Migration& m : migrations) {
    if (m.version <= outcome.version) continue;

    // one transaction per migration: all of its statements and its bookkeeping row
    if (!db.transaction()) {
      outcome.result = MigrationResult::Failed;
      outcome.failedVersion = m.version;
      outcome.driverMessage = db.lastError().text();
      return outcome;
    }
    QSqlQuery q(db);
    bool ok = true;
    for (const QString& statement : statementsFor(m.sql, driverOf(db))) {
      if (!q.exec(statement)) {
        ok = false;
        break;
      }
    }
    if (ok) {
      q.prepare(QStringLiteral(
          "INSERT INTO schema_migrations (version, name, applied_at) VALUES (?, ?, ?)"));
      q.addBindValue(m.version);
      q.addBindValue(m.name);
      q.addBindValue(QDateTime::currentDateTimeUtc().toString(Qt::ISODate));
      ok = q.exec();
    }
    // what SQLite did not check while its foreign keys were off
    const QString violations = ok && driverOf(db) == Driver::SQLite ? foreignKeyViolations(db) : QString();
    if (!ok || !violations.isEmpty() || !db.commit()) {
      outcome.driverMessage = violations.isEmpty() ? q.lastError().text() : violations;
      db.rollback();
      outcome.result = MigrationResult::Failed;
      outcome.failedVersion = m.version;
      return outcome;
    }
    outcome.version = m.version;
  }
  return outcome;
}

}  // namespace microsim::assessment
