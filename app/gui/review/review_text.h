#pragma once
// The review screens' words for what the assessment hands out as keys and enums: feedback
// keys of the rubrics, attempt modes and statuses. Metric and pierce-field names are the app's
// one vocabulary (gui/metric_vocabulary.h), values with units gui/number_format.h. Unknown
// keys come back verbatim, so a newer rubric still shows something readable.

#include "microsim/assessment/storage/history_types.h"

#include <QCoreApplication>
#include <QString>

namespace microsim::gui {

class ReviewText {
  Q_DECLARE_TR_FUNCTIONS(microsim::gui::ReviewText)

 public:
  /// A sentence for a feedback key such as "entry_angle.too_oblique"; empty for none.
  static QString feedback(const QString& key);
  static QString mode(assessment::AttemptMode mode);
  static QString status(assessment::AttemptStatus status);
};

}  // namespace microsim::gui
