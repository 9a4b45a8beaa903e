#pragma once
// The role check every store makes before it hands out or annotates attempts: the viewer's
// claimed role must be the one stored for that person, and a trainee may reach only their
// own attempts.

#include "microsim/assessment/storage/history_database.h"

#include <optional>

namespace microsim::assessment::access {

/// The stored role of a person; nullopt when unknown (or the query failed).
std::optional<Role> storedRole(const QSqlDatabase& db, qint64 personId);

/// None when `viewer` may read the attempts of `traineeId` (nullopt: of everyone, which a
/// trainee's own list also passes, narrowed by the caller); Forbidden otherwise.
HistoryError mayView(const QSqlDatabase& db, const Viewer& viewer, std::optional<qint64> traineeId);

/// None when `viewer` may read attempt `attemptId`; Forbidden, NotFound or QueryFailed
/// (with the driver's text) otherwise.
HistoryStatus mayViewAttempt(const QSqlDatabase& db, const Viewer& viewer, qint64 attemptId);

}  // namespace microsim::assessment::access
