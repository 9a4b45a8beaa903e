#pragma once
// The app's one vocabulary for the scoring's keys: every metric key of assessment's metric
// catalogue (metrics.h) and every per-pierce field (pierce_fields.h) with its translatable
// label. Units stay in those catalogues; this table adds only the words. The results page,
// the review's tables and charts and the reports all name a metric through here, so that a
// label is written once and cannot drift between screens. An unknown key (a newer rubric's)
// comes back verbatim, so it still shows something readable.

#include <QCoreApplication>
#include <QString>

#include <string_view>

namespace microsim::gui {

class MetricVocabulary {
  Q_DECLARE_TR_FUNCTIONS(microsim::gui::MetricVocabulary)

 public:
  /// "Entry angle" for the metric "entry_angle".
  static QString metricLabel(std::string_view key);
  static QString metricLabel(const QString& key);
  /// The metric's unit in the scoring's catalogue ("s", "mm", "deg", "count", "1"); empty
  /// for an unknown key.
  static QString metricUnit(const QString& key);
  /// Whether the metric has a label of its own here (false: the key is shown verbatim).
  static bool hasMetricLabel(std::string_view key);

  /// "Entry angle" for the pierce field "entry_angle_deg".
  static QString pierceFieldLabel(std::string_view key);
  /// A pierce table's column title: the label with the field's unit, "Entry angle (°)".
  static QString pierceFieldTitle(std::string_view key);
  /// Whether the pierce field has a label of its own here.
  static bool hasPierceFieldLabel(std::string_view key);

  /// "°" for "deg", "mm" and "s" as they are, empty for counts, ratios and flags.
  static QString unitSymbol(std::string_view unit);
};

}  // namespace microsim::gui
