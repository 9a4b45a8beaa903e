#include "cli/history_text.h"

#include "microsim/assessment/storage/people_store.h"

namespace microsim::cli {

namespace {

using assessment::DatabaseError;
using assessment::HistoryError;

QString withDriverMessage(const QString& text, const QString& driverMessage) {
  return driverMessage.isEmpty() ? text
                                 : text + QStringLiteral(" (") + driverMessage + QLatin1Char(')');
}

QString databaseErrorWords(DatabaseError error, const QString& location) {
  switch (error) {
    case DatabaseError::None:
      return {};
    case DatabaseError::CannotCreateFolder:
      return Cli::tr("cannot create the folder for %1").arg(location);
    case DatabaseError::CannotOpen:
      return Cli::tr("cannot open %1").arg(location);
    case DatabaseError::NotADatabase:
      return Cli::tr("%1 is not a microsim database or is damaged; it was left untouched")
          .arg(location);
    case DatabaseError::Locked:
      return Cli::tr("%1 is locked by another program").arg(location);
    case DatabaseError::NewerSchema:
      return Cli::tr("%1 was written by a newer microsim").arg(location);
    case DatabaseError::MigrationFailed:
      return Cli::tr("updating %1 failed; it was left as it was").arg(location);
    case DatabaseError::ReadOnly:
      return Cli::tr("%1 is read-only; it was left untouched").arg(location);
  }
  return {};
}

QString historyErrorWords(HistoryError error) {
  switch (error) {
    case HistoryError::None:
      return {};
    case HistoryError::NotOpen:
      return Cli::tr("the database is not open");
    case HistoryError::Forbidden:
      return Cli::tr("not allowed for this user");
    case HistoryError::NotFound:
      return Cli::tr("no such person or attempt");
    case HistoryError::NotInProgress:
      return Cli::tr("the attempt is already finished");
    case HistoryError::NameTaken:
      return Cli::tr("that name is taken");
    case HistoryError::InvalidInput:
      return Cli::tr("empty name, or a password shorter than %1 characters")
          .arg(assessment::PeopleStore::kMinPasswordLength);
    case HistoryError::WrongPassword:
      return Cli::tr("unknown instructor or wrong password");
    case HistoryError::Unsupported:
      return Cli::tr("not possible on a PostgreSQL server (use pg_dump and pg_restore there)");
    case HistoryError::NotABackup:
      return Cli::tr("the file is not a microsim history");
    case HistoryError::BackupTooNew:
      return Cli::tr("the backup was written by a newer microsim");
    case HistoryError::FileError:
      return Cli::tr("the file could not be read or written");
    case HistoryError::QueryFailed:
      return Cli::tr("the database reported an error");
  }
  return {};
}

}  // namespace

QString databaseErrorText(const assessment::DatabaseStatus& status, const QString& location) {
  return withDriverMessage(databaseErrorWords(status.error, location), status.driverMessage);
}

QString historyErrorText(const assessment::HistoryStatus& status) {
  return withDriverMessage(historyErrorWords(status.error), status.driverMessage);
}

}  // namespace microsim::cli
