#pragma once
// The words for the history database's errors, shared by the commands that use it (db, score).
#include "cli/cli.h"

#include "microsim/assessment/storage/history_database.h"

namespace microsim::cli {

/// Why `location` could not be opened, with the driver's own message when it gave one.
QString databaseErrorText(const assessment::DatabaseStatus& status, const QString& location);

/// Why an operation on an open history failed, with the driver's own message when it gave one.
QString historyErrorText(const assessment::HistoryStatus& status);

}  // namespace microsim::cli
