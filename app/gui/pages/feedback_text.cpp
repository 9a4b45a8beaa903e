#include "gui/pages/feedback_text.h"

#include <cmath>
#include <map>

namespace microsim::gui {

QString FeedbackText::metricName(const std::string& key) {
  static const std::map<std::string, const char*> names = {
      {"time", QT_TR_NOOP("Time")},
      {"path_length", QT_TR_NOOP("Path length")},
      {"path_length_left", QT_TR_NOOP("Path length, left hand")},
      {"path_length_right", QT_TR_NOOP("Path length, right hand")},
      {"movements", QT_TR_NOOP("Movements")},
      {"smoothness", QT_TR_NOOP("Smoothness")},
      {"idle_time", QT_TR_NOOP("Idle time")},
      {"regrasps", QT_TR_NOOP("Re-grasps")},
      {"suture_breaks", QT_TR_NOOP("Suture breaks")},
      {"max_stretch", QT_TR_NOOP("Largest tissue stretch")},
      {"tissue_damage", QT_TR_NOOP("Tissue damage")},
      {"passages", QT_TR_NOOP("Wall passages")},
      {"arc_deviation", QT_TR_NOOP("Needle off its arc")},
      {"entry_angle", QT_TR_NOOP("Entry angle")},
      {"exit_angle", QT_TR_NOOP("Exit angle")},
      {"bite", QT_TR_NOOP("Bite")},
      {"bite_walls", QT_TR_NOOP("Bite in wall thicknesses")},
      {"full_thickness", QT_TR_NOOP("Full-thickness bites")},
      {"back_wall_catches", QT_TR_NOOP("Back-wall catches")},
      {"stitches", QT_TR_NOOP("Stitches")},
      {"bite_symmetry", QT_TR_NOOP("Bite symmetry")},
      {"spacing", QT_TR_NOOP("Stitch spacing")},
      {"triangulation_error", QT_TR_NOOP("Triangulation error")},
  };
  const auto it = names.find(key);
  return it == names.end() ? QString::fromStdString(key) : tr(it->second);
}

QString FeedbackText::advice(const std::string& key) {
  static const std::map<std::string, const char*> advice = {
      {"bite.asymmetric", QT_TR_NOOP("Take the same bite on both ends.")},
      {"bite.partial_thickness", QT_TR_NOOP("Pass through the whole wall, not only part of it.")},
      {"bite.too_long", QT_TR_NOOP("Enter closer to the cut edge.")},
      {"bite.too_short", QT_TR_NOOP("Enter further from the cut edge: the stitch may tear out.")},
      {"entry_angle.too_oblique", QT_TR_NOOP("Enter the wall more perpendicularly.")},
      {"exit_angle.too_oblique", QT_TR_NOOP("Follow the needle's curve so it leaves the wall perpendicularly.")},
      {"handling.too_many_regrasps", QT_TR_NOOP("Re-grasp less: plan each grip.")},
      {"motion.hesitant", QT_TR_NOOP("Fewer pauses: keep the movement going.")},
      {"motion.jerky", QT_TR_NOOP("Move more smoothly.")},
      {"motion.wasted_path", QT_TR_NOOP("Shorter, more direct instrument paths.")},
      {"never.back_wall_catch", QT_TR_NOOP("The back wall was caught: this closes the vessel.")},
      {"never.suture_break", QT_TR_NOOP("The suture broke: pull more gently.")},
      {"never.tissue_tear", QT_TR_NOOP("The tissue was torn or over-stretched.")},
      {"pierce.not_done", QT_TR_NOOP("The needle did not pass through the wall.")},
      {"pierce.extra_passages", QT_TR_NOOP("Pass each wall once: every extra passage injures it.")},
      {"pierce.off_arc", QT_TR_NOOP("Turn the needle along its curve instead of pushing it.")},
      {"never.needle_dragged", QT_TR_NOOP("The needle was dragged sideways through the tissue, not turned along its curve.")},
      {"stitch.not_completed", QT_TR_NOOP("The stitch was not completed through both ends.")},
      {"stitch.too_few", QT_TR_NOOP("Too few stitches.")},
      {"stitch.too_many", QT_TR_NOOP("More stitches than needed.")},
      {"time.too_slow", QT_TR_NOOP("Work faster.")},
      {"tissue.over_stretched", QT_TR_NOOP("Handle the tissue more gently: it was over-stretched.")},
      {"triangulation.uneven", QT_TR_NOOP("Space the first three stitches 120° apart.")},
  };
  if (key.empty()) return {};
  const auto it = advice.find(key);
  if (it != advice.end()) return tr(it->second);
  const std::size_t dot = key.rfind('.');
  const std::string metric = key.substr(0, dot);
  const std::string kind = dot == std::string::npos ? std::string() : key.substr(dot + 1);
  if (kind == "missing") return tr("%1: not measured in this attempt.").arg(metricName(metric));
  if (kind == "not_applicable")
    return tr("%1: not applicable to this input; not counted.").arg(metricName(metric));
  if (kind == "too_high") return tr("%1 is too high.").arg(metricName(metric));
  if (kind == "too_low") return tr("%1 is too low.").arg(metricName(metric));
  return QString::fromStdString(key);
}

QString FeedbackText::value(double v, const std::string& unit, const QString& units) {
  if (!std::isfinite(v)) return QStringLiteral("–");
  if (unit == "mm") {
    if (units == QLatin1String("um")) return tr("%1 µm").arg(v * 1000.0, 0, 'f', 0);
    return tr("%1 mm").arg(v, 0, 'f', 3);
  }
  if (unit == "s") return tr("%1 s").arg(v, 0, 'f', 1);
  if (unit == "deg") return tr("%1°").arg(v, 0, 'f', 1);
  if (unit == "count") return QString::number(v, 'f', 0);
  return QString::number(v, 'g', 3);
}

}  // namespace microsim::gui
