#pragma once
// Versioned schema as data: numbered SQL files bundled as Qt resources
// (assessment/migrations/NNNN_name.sql). A migration's statements end with ';' at the
// end of a line. Each pending migration runs, with its row in schema_migrations, in
// one transaction: a database is always at a whole version, never between two.
//
// One text serves SQLite and PostgreSQL. The runner substitutes, per driver:
//   @ID@    INTEGER PRIMARY KEY          | BIGSERIAL PRIMARY KEY
//   @BLOB@  BLOB                         | BYTEA
//   @REAL@  REAL                         | DOUBLE PRECISION
// and a statement that begins with @SQLITE@ or @POSTGRESQL@ runs on that driver only
// (for what the dialects spell differently, such as triggers). Timestamps are ISO-8601
// TEXT in UTC. A statement may hold ';' inside a line (a trigger body written on one
// line); only a ';' that ends a line ends a statement.
//
// On SQLite the migrations run with foreign key enforcement off (a table rebuild, SQLite's
// way to change a constraint, would otherwise cascade the old table's drop into its
// children), and each is committed only when PRAGMA foreign_key_check finds no row that
// breaks a foreign key; the setting is put back afterwards.

#include <QSqlDatabase>
#include <QString>

#include <vector>

namespace microsim::assessment {

enum class Driver { SQLite, PostgreSQL };

/// The driver behind a QtSql connection (QSQLITE or QPSQL).
Driver driverOf(const QSqlDatabase& db);

/// `sql` with the placeholders replaced for `driver`; statements marked for the other
/// driver are dropped.
QStringList statementsFor(const QString& sql, Driver driver);

struct Migration {
  int version = 0;
  QString name;  ///< the file name, e.g. "0001_initial.sql"
  QString sql;
};

/// The migrations shipped in the binary, sorted by version.
std::vector<Migration> bundledMigrations();

/// The statements of one migration's SQL text, comments and blank lines removed.
QStringList splitStatements(const QString& sql);

enum class MigrationResult {
  Ok,
  NewerSchema,  ///< the database was written by a newer microsim; left untouched
  Failed,       ///< a statement failed; the transaction was rolled back
};

struct MigrationOutcome {
  MigrationResult result = MigrationResult::Ok;
  int version = 0;          ///< the schema version after the call
  int failedVersion = 0;    ///< with Failed: the migration that failed
  QString driverMessage;    ///< with Failed: the driver's text (data, not for display as is)
};

/// The version recorded in schema_migrations (0 for a new database).
int schemaVersion(QSqlDatabase& db);

/// Applies every migration in `migrations` newer than the database's version, with the
/// placeholders of the connection's driver.
MigrationOutcome migrate(QSqlDatabase& db, const std::vector<Migration>& migrations);

}  // namespace microsim::assessment
