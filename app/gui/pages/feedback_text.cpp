#include "gui/pages/feedback_text.h"

#include "gui/metric_vocabulary.h"

#include <map>

namespace microsim::gui {

QString FeedbackText::advice(const std::string& key) {
  static const std::map<std::string, const char*> advice = {
      {"bite.asymmetric", QT_TR_NOOP("Take the same bite on both ends.")},
      {"bite.partial_thickness", QT_TR_NOOP("Pass through the whole wall, not only part of it.")},
      {"bite.too_long", QT_TR_NOOP("Enter closer to the cut edge.")},
      {"bite.too_short", QT_TR_NOOP("Enter further from the cut edge: the stitch may tear out.")},
      {"cut.not_done", QT_TR_NOOP("Cut both tails of every knot with the microscissors (T).")},
      {"cut_end.too_long", QT_TR_NOOP("Cut the tails shorter: about 1 mm from the knot.")},
      {"cut_end.too_short",
       QT_TR_NOOP("Leave longer tails, about 1 mm: a tail cut at the knot lets it untie.")},
      {"end_product.lapses",
       QT_TR_NOOP("The finished anastomosis has errors: see the list of lapses.")},
      {"entry_angle.too_oblique", QT_TR_NOOP("Enter the wall more perpendicularly.")},
      {"exit_angle.too_oblique",
       QT_TR_NOOP("Follow the needle's curve so it leaves the wall perpendicularly.")},
      {"handling.too_many_regrasps", QT_TR_NOOP("Re-grasp less: plan each grip.")},
      {"knot.not_secure",
       QT_TR_NOOP(
           "Tie a square or surgeon's knot: a double throw, then a single throw the other way.")},
      {"knot.not_tied", QT_TR_NOOP("Tie every stitch: wrap the thread round the forceps, grasp the "
                                   "tail, pull it through.")},
      {"knot.too_few_throws",
       QT_TR_NOOP("Lay at least two throws, the second the other way round.")},
      {"motion.hesitant", QT_TR_NOOP("Fewer pauses: keep the movement going.")},
      {"motion.jerky", QT_TR_NOOP("Move more smoothly.")},
      {"motion.wasted_path", QT_TR_NOOP("Shorter, more direct instrument paths.")},
      {"never.back_wall_catch", QT_TR_NOOP("The back wall was caught: this closes the vessel.")},
      {"never.suture_break", QT_TR_NOOP("The suture broke: pull more gently.")},
      {"never.tissue_tear", QT_TR_NOOP("The tissue was torn or over-stretched.")},
      {"pierce.not_done", QT_TR_NOOP("The needle did not pass through the wall.")},
      {"pierce.extra_passages", QT_TR_NOOP("Pass each wall once: every extra passage injures it.")},
      {"pierce.off_arc", QT_TR_NOOP("Turn the needle along its curve instead of pushing it.")},
      {"never.leak",
       QT_TR_NOOP(
           "The suture line leaks under pressure: close the widest gap with another stitch.")},
      {"never.knot_slipped",
       QT_TR_NOOP(
           "A knot slipped: the stitch would open. Alternate the throws and snug each one down.")},
      {"never.needle_dragged",
       QT_TR_NOOP(
           "The needle was dragged sideways through the tissue, not turned along its curve.")},
      {"stitch.not_completed", QT_TR_NOOP("The stitch was not completed through both ends.")},
      {"stitch.too_few", QT_TR_NOOP("Too few stitches.")},
      {"stitch.too_many", QT_TR_NOOP("More stitches than needed.")},
      {"task.not_done", QT_TR_NOOP("Counts only once part of the task is done.")},
      {"time.too_slow", QT_TR_NOOP("Work faster.")},
      {"tissue.over_stretched",
       QT_TR_NOOP("Handle the tissue more gently: it was over-stretched.")},
      {"triangulation.uneven", QT_TR_NOOP("Space the first three stitches 120° apart.")},
  };
  if (key.empty()) return {};
  const auto it = advice.find(key);
  if (it != advice.end()) return tr(it->second);
  const std::size_t dot = key.rfind('.');
  const std::string metric = key.substr(0, dot);
  const std::string kind = dot == std::string::npos ? std::string() : key.substr(dot + 1);
  if (kind == "missing") return tr("%1: not measured in this attempt.").arg(MetricVocabulary::metricLabel(metric));
  if (kind == "not_applicable")
    return tr("%1: not applicable to this input; not counted.").arg(MetricVocabulary::metricLabel(metric));
  if (kind == "too_high") return tr("%1 is too high.").arg(MetricVocabulary::metricLabel(metric));
  if (kind == "too_low") return tr("%1 is too low.").arg(MetricVocabulary::metricLabel(metric));
  return QString::fromStdString(key);
}

}  // namespace microsim::gui
