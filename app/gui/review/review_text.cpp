#include "gui/review/review_text.h"

#include "gui/metric_vocabulary.h"

#include <QHash>

namespace microsim::gui {

QString ReviewText::feedback(const QString& key) {
  static const QHash<QString, const char*> sentences = {
      {QStringLiteral("task.not_done"),
       QT_TR_NOOP("Nothing of the task was done, so time and handling were not scored.")},
      {QStringLiteral("time.too_slow"), QT_TR_NOOP("Took longer than the target time.")},
      {QStringLiteral("motion.wasted_path"),
       QT_TR_NOOP("The instruments travelled further than needed.")},
      {QStringLiteral("motion.jerky"),
       QT_TR_NOOP("Movements were jerky; aim for smooth, continuous motion.")},
      {QStringLiteral("motion.hesitant"), QT_TR_NOOP("Long pauses with both hands still.")},
      {QStringLiteral("tissue.over_stretched"), QT_TR_NOOP("The tissue was stretched too far.")},
      {QStringLiteral("handling.too_many_regrasps"), QT_TR_NOOP("Too many re-grasps.")},
      {QStringLiteral("pierce.not_done"), QT_TR_NOOP("The wall was not passed with the needle.")},
      {QStringLiteral("pierce.extra_passages"),
       QT_TR_NOOP("The wall was passed more often than needed.")},
      {QStringLiteral("pierce.off_arc"),
       QT_TR_NOOP("The needle was pushed rather than turned along its curve.")},
      {QStringLiteral("never.needle_dragged"),
       QT_TR_NOOP("The needle was dragged sideways through the tissue.")},
      {QStringLiteral("entry_angle.too_oblique"),
       QT_TR_NOOP("The needle entered too obliquely; enter perpendicular to the wall.")},
      {QStringLiteral("exit_angle.too_oblique"),
       QT_TR_NOOP("The needle came out too obliquely; follow its curve.")},
      {QStringLiteral("bite.too_long"), QT_TR_NOOP("Bites too far from the edge.")},
      {QStringLiteral("bite.too_short"), QT_TR_NOOP("Bites too close to the edge.")},
      {QStringLiteral("bite.partial_thickness"),
       QT_TR_NOOP("Some passages did not go through the whole wall.")},
      {QStringLiteral("bite.asymmetric"),
       QT_TR_NOOP("The two bites of a stitch differ in length.")},
      {QStringLiteral("stitch.not_completed"), QT_TR_NOOP("Not all stitches were completed.")},
      {QStringLiteral("stitch.too_few"), QT_TR_NOOP("Too few stitches.")},
      {QStringLiteral("stitch.too_many"), QT_TR_NOOP("More stitches than needed.")},
      {QStringLiteral("triangulation.uneven"),
       QT_TR_NOOP("The first stitches are not spaced 120° apart.")},
      {QStringLiteral("knot.not_tied"), QT_TR_NOOP("Not every stitch was tied.")},
      {QStringLiteral("knot.not_secure"), QT_TR_NOOP("Knots were not square or surgeon's knots.")},
      {QStringLiteral("knot.too_few_throws"), QT_TR_NOOP("Knots had too few throws.")},
      {QStringLiteral("cut.not_done"), QT_TR_NOOP("Not every tail was cut.")},
      {QStringLiteral("cut_end.too_long"), QT_TR_NOOP("Tails were left too long.")},
      {QStringLiteral("cut_end.too_short"), QT_TR_NOOP("Tails were cut too short.")},
      {QStringLiteral("end_product.lapses"), QT_TR_NOOP("The finished anastomosis has lapses.")},
      {QStringLiteral("never.leak"), QT_TR_NOOP("The suture line leaked under pressure.")},
      {QStringLiteral("never.knot_slipped"), QT_TR_NOOP("A knot slipped: the stitch would open.")},
      {QStringLiteral("never.back_wall_catch"),
       QT_TR_NOOP("The back wall was caught: the lumen would be closed.")},
      {QStringLiteral("never.suture_break"), QT_TR_NOOP("The suture broke.")},
      {QStringLiteral("never.tissue_tear"), QT_TR_NOOP("The tissue was torn or over-stretched.")},
  };
  if (key.isEmpty()) return {};
  auto it = sentences.constFind(key);
  if (it != sentences.cend()) return tr(it.value());
  // the scoring's default keys: "<metric>.missing", "<metric>.not_applicable",
  // "<metric>.too_high", "<metric>.too_low"
  const QString metric = MetricVocabulary::metricLabel(key.section(QLatin1Char('.'), 0, 0));
  const QString kind = key.section(QLatin1Char('.'), 1);
  if (kind == QStringLiteral("missing")) return tr("%1: not measured in this attempt.").arg(metric);
  if (kind == QStringLiteral("not_applicable"))
    return tr("%1: not applicable to this input; not counted.").arg(metric);
  if (kind == QStringLiteral("too_high")) return tr("%1 too high.").arg(metric);
  if (kind == QStringLiteral("too_low")) return tr("%1 too low.").arg(metric);
  return key;
}

QString ReviewText::mode(assessment::AttemptMode mode) {
  return mode == assessment::AttemptMode::Test ? tr("Test") : tr("Learn");
}

QString ReviewText::status(assessment::AttemptStatus status) {
  switch (status) {
    case assessment::AttemptStatus::InProgress: return tr("In progress");
    case assessment::AttemptStatus::Finished: return tr("Finished");
    case assessment::AttemptStatus::Interrupted: return tr("Interrupted");
    case assessment::AttemptStatus::Abandoned: return tr("Abandoned");
  }
  return {};
}

}  // namespace microsim::gui
