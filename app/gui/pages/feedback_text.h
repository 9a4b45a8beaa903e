#pragma once
// Words for the scoring's keys (assessment returns keys, the app translates them): a feedback
// key's advice and a value in its unit with the units setting applied. Metric names are the
// app's one vocabulary (gui/metric_vocabulary.h).

#include <QCoreApplication>
#include <QString>

#include <string>

namespace microsim::gui {

class FeedbackText {
  Q_DECLARE_TR_FUNCTIONS(microsim::gui::FeedbackText)

 public:
  /// "entry_angle.too_oblique" → advice; "<key>.missing", "<key>.too_high/too_low" generic.
  static QString advice(const std::string& feedbackKey);
  /// A value with its unit ("s", "mm", "deg", "count", "1"); mm shown in µm when `units` is
  /// "um"; NaN as a dash.
  static QString value(double v, const std::string& unit, const QString& units);
};

}  // namespace microsim::gui
