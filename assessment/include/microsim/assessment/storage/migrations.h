#pragma once
// Versioned schema as data: numbered SQL files bundled as Qt resources
// (assessment/migrations/NNNN_name.sql). A migration's statements end with ';' at the
// end of a line. Each pending migration runs, with its row in schema_migrations, in
// one transaction: a database is always at a whole version, never between two.

#include <QSqlDatabase>
#include <QString>

#include <vector>

namespace microsim::assessment {

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

/// Applies every migration in `migrations` newer than the database's version.
MigrationOutcome migrate(QSqlDatabase& db, const std::vector<Migration>& migrations);

}  // namespace microsim::assessment
