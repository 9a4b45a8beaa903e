#include "gui/metric_vocabulary.h"

#include "microsim/assessment/scoring/metrics.h"
#include "microsim/assessment/scoring/pierce_fields.h"

#include <algorithm>
#include <array>
#include <utility>

namespace microsim::gui {

namespace {

using KeyLabel = std::pair<std::string_view, const char*>;

// metric key → label, in the scoring catalogue's order
constexpr std::array<KeyLabel, 36> kMetricLabels{{
    {"time", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Time")},
    {"path_length", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Path length")},
    {"path_length_left", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Path length, left hand")},
    {"path_length_right", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Path length, right hand")},
    {"movements", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Movements")},
    {"smoothness", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Smoothness")},
    {"idle_time", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Idle time")},
    {"regrasps", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Re-grasps")},
    {"suture_breaks", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Suture breaks")},
    {"max_stretch", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Largest tissue stretch")},
    {"tissue_damage", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Tissue damage")},
    {"passages", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Wall passages")},
    {"arc_deviation", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Needle off its arc")},
    {"entry_angle", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Entry angle")},
    {"exit_angle", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Exit angle")},
    {"bite", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Bite")},
    {"bite_walls", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Bite in wall thicknesses")},
    {"full_thickness", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Full-thickness passages")},
    {"back_wall_catches", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Back-wall catches")},
    {"stitches", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Stitches")},
    // the metric is |bite_a − bite_b|: higher is worse, so it names the asymmetry
    {"bite_symmetry", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Bite asymmetry")},
    {"spacing", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Stitch spacing")},
    {"triangulation_error", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Triangulation error")},
    {"lapse_index", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Anastomosis lapse index")},
    {"oblique_stitches", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Oblique stitches")},
    {"partial_thickness_bites", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Partial-thickness bites")},
    {"wide_bites", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Wide bites")},
    {"unequal_spacing", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Unequally spaced stitches")},
    {"knots_tied", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Knots tied")},
    {"secure_knots", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Secure knots")},
    {"knots_slipped", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Knots slipped")},
    {"knot_throws", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Throws per knot")},
    {"thread_cuts", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Tails cut")},
    {"cut_end_length", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Cut-end length")},
    {"leaks", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Leaks under pressure")},
    {"leak_gap", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Largest gap under pressure")},
}};

// pierce field key → label, in pierceFields() order
constexpr std::array<KeyLabel, 8> kPierceFieldLabels{{
    {"time_s", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Time")},
    {"entry_angle_deg", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Entry angle")},
    {"exit_angle_deg", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Exit angle")},
    {"bite_mm", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Bite")},
    {"bite_walls", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Bite in wall thicknesses")},
    {"circumference_deg", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Position")},
    {"full_thickness", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Full thickness")},
    {"back_wall", QT_TRANSLATE_NOOP("microsim::gui::MetricVocabulary", "Back wall")},
}};

template <std::size_t N>
const char* labelSourceOf(const std::array<KeyLabel, N>& table, std::string_view key) {
  const auto it = std::find_if(table.begin(), table.end(), [key](const KeyLabel& e) { return e.first == key; });
  return it == table.end() ? nullptr : it->second;
}

QString verbatim(std::string_view key) { return QString::fromUtf8(key.data(), qsizetype(key.size())); }

}  // namespace

QString MetricVocabulary::metricLabel(std::string_view key) {
  const char* source = labelSourceOf(kMetricLabels, key);
  return source ? tr(source) : verbatim(key);
}

QString MetricVocabulary::metricLabel(const QString& key) { return metricLabel(std::string_view(key.toStdString())); }

QString MetricVocabulary::metricUnit(const QString& key) {
  const assessment::MetricInfo* info = assessment::findMetric(key.toStdString());
  return info ? verbatim(info->unit) : QString();
}

bool MetricVocabulary::hasMetricLabel(std::string_view key) { return labelSourceOf(kMetricLabels, key) != nullptr; }

QString MetricVocabulary::pierceFieldLabel(std::string_view key) {
  const char* source = labelSourceOf(kPierceFieldLabels, key);
  return source ? tr(source) : verbatim(key);
}

QString MetricVocabulary::pierceFieldTitle(std::string_view key) {
  const auto fields = assessment::pierceFields();
  const auto it = std::find_if(fields.begin(), fields.end(),
                               [key](const assessment::PierceField& f) { return f.key == key; });
  const QString symbol = it == fields.end() ? QString() : unitSymbol(it->unit);
  const QString label = pierceFieldLabel(key);
  return symbol.isEmpty() ? label : tr("%1 (%2)", "a label and its unit").arg(label, symbol);
}

bool MetricVocabulary::hasPierceFieldLabel(std::string_view key) {
  return labelSourceOf(kPierceFieldLabels, key) != nullptr;
}

QString MetricVocabulary::unitSymbol(std::string_view unit) {
  if (unit == "deg") return QStringLiteral("°");
  if (unit == "count" || unit == "1" || unit == "flag") return {};
  return verbatim(unit);
}

}  // namespace microsim::gui
