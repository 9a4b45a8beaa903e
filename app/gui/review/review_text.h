#pragma once
// The review screens' words for what the assessment hands out as keys and enums: metric
// keys (metrics.h), feedback keys of the rubrics, attempt modes and statuses, pierce values.
// Unknown keys come back verbatim, so a newer rubric still shows something readable.

#include "microsim/assessment/storage/history_types.h"

#include <QCoreApplication>
#include <QString>

namespace microsim::gui {

class ReviewText {
  Q_DECLARE_TR_FUNCTIONS(microsim::gui::ReviewText)

 public:
  /// "Entry angle" for "entry_angle".
  static QString metricName(const QString& key);
  /// "°" for "deg", "mm", "s", empty for counts and ratios.
  static QString unitSymbol(const QString& unit);
  /// A sentence for a feedback key such as "entry_angle.too_oblique"; empty for none.
  static QString feedback(const QString& key);
  static QString mode(assessment::AttemptMode mode);
  static QString status(assessment::AttemptStatus status);
  /// Column title of a stored per-pierce value ("entry_angle_deg", "bite_mm", ...).
  static QString pierceValueName(const QString& key);
  /// A value with its unit, "12.3 mm"; "–" for NaN.
  static QString value(double value, const QString& unit, int decimals = 1);
};

}  // namespace microsim::gui
