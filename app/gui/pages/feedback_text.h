#pragma once
// Words for the scoring's keys (assessment returns keys, the app translates them): a feedback
// key's advice. Metric names are the app's one vocabulary (gui/metric_vocabulary.h), numbers
// with their units gui/number_format.h.

#include <QCoreApplication>
#include <QString>

#include <string>

namespace microsim::gui {

class FeedbackText {
  Q_DECLARE_TR_FUNCTIONS(microsim::gui::FeedbackText)

 public:
  /// "entry_angle.too_oblique" → advice; "<key>.missing", "<key>.too_high/too_low" generic.
  static QString advice(const std::string& feedbackKey);
};

}  // namespace microsim::gui
