#pragma once
// Words for the scoring's keys (assessment returns keys, the app translates them): a metric's
// name, a feedback key's advice, and a value in its unit with the units setting applied.

#include <QCoreApplication>
#include <QString>

#include <string>

namespace microsim::gui {

class FeedbackText {
  Q_DECLARE_TR_FUNCTIONS(microsim::gui::FeedbackText)

 public:
  /// "entry_angle" → "Entry angle"; an unknown key is returned as it is.
  static QString metricName(const std::string& key);
  /// "entry_angle.too_oblique" → advice; "<key>.missing", "<key>.too_high/too_low" generic.
  static QString advice(const std::string& feedbackKey);
  /// A value with its unit ("s", "mm", "deg", "count", "1"); mm shown in µm when `units` is
  /// "um"; NaN as a dash.
  static QString value(double v, const std::string& unit, const QString& units);
};

}  // namespace microsim::gui
