#pragma once
// Conversions between the history's values and their SQL columns (both drivers).

#include "microsim/assessment/storage/history_types.h"

#include <QDateTime>
#include <QString>
#include <QVariant>

#include <cmath>
#include <limits>
#include <string>
#include <optional>

namespace microsim::assessment::sql {

/// Now, as stored: ISO-8601 UTC with milliseconds.
inline QString now() { return QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs); }

inline QDateTime time(const QVariant& v) {
  return v.isNull() ? QDateTime() : QDateTime::fromString(v.toString(), Qt::ISODateWithMs);
}

inline QString roleText(Role r) {
  return r == Role::Instructor ? QStringLiteral("instructor") : QStringLiteral("trainee");
}
inline std::optional<Role> roleFromText(const QString& s) {
  if (s == QLatin1String("trainee")) return Role::Trainee;
  if (s == QLatin1String("instructor")) return Role::Instructor;
  return std::nullopt;
}

inline QString modeText(AttemptMode m) {
  return m == AttemptMode::Test ? QStringLiteral("test") : QStringLiteral("learn");
}
inline AttemptMode modeFromText(const QString& s) {
  return s == QLatin1String("test") ? AttemptMode::Test : AttemptMode::Learn;
}

inline QString statusText(AttemptStatus s) {
  switch (s) {
    case AttemptStatus::Finished:
      return QStringLiteral("finished");
    case AttemptStatus::Interrupted:
      return QStringLiteral("interrupted");
    case AttemptStatus::Abandoned:
      return QStringLiteral("abandoned");
    case AttemptStatus::InProgress:
      break;
  }
  return QStringLiteral("in_progress");
}
inline AttemptStatus statusFromText(const QString& s) {
  if (s == QLatin1String("finished")) return AttemptStatus::Finished;
  if (s == QLatin1String("interrupted")) return AttemptStatus::Interrupted;
  if (s == QLatin1String("abandoned")) return AttemptStatus::Abandoned;
  return AttemptStatus::InProgress;
}

/// Never NULL: an empty string stays an empty string in a NOT NULL column.
inline QString text(const QString& s) { return s.isNull() ? QStringLiteral("") : s; }
inline QString text(const std::string& s) { return text(QString::fromStdString(s)); }

/// NaN and infinities are stored as NULL.
inline QVariant real(double v) {
  return std::isfinite(v) ? QVariant(v) : QVariant(QMetaType(QMetaType::Double));
}
inline double realOrNan(const QVariant& v) {
  return v.isNull() ? std::numeric_limits<double>::quiet_NaN() : v.toDouble();
}

/// A 0-based index, or NULL for none (−1).
inline QVariant index(int i) {
  return i >= 0 ? QVariant(i) : QVariant(QMetaType(QMetaType::Int));
}
inline int indexOrNone(const QVariant& v) {
  return v.isNull() ? -1 : v.toInt();
}

}  // namespace microsim::assessment::sql
