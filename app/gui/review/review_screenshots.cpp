#include "gui/review/review_screenshots.h"

#include "gui/pages/end_product_panel.h"
#include "gui/review/attempt_detail_view.h"
#include "gui/review/review_page.h"
#include "lesson/lesson.h"
#include "microsim/assessment/scoring/score.h"
#include "microsim/assessment/storage/annotation_store.h"
#include "microsim/assessment/storage/attempt_store.h"
#include "microsim/assessment/storage/people_store.h"
#include "microsim/assessment/storage/score_store.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QPixmap>
#include <QTabWidget>
#include <QTemporaryDir>

#include <limits>
#include <variant>

namespace microsim::gui {
namespace {

using assessment::AttemptMode;

// a score through the scoring API: every rubric metric at its target except those given
assessment::AttemptScore demoScore(const assessment::Rubric& rubric, const std::map<std::string, double>& values) {
  std::vector<assessment::MetricValue> metrics;
  for (const assessment::RubricMetric& m : rubric.metrics) {
    auto it = values.find(m.key);
    const assessment::MetricInfo* info = assessment::findMetric(m.key);
    metrics.push_back({m.key, it == values.end() ? m.target : it->second, info ? std::string(info->unit) : std::string()});
  }
  assessment::AttemptScore score = assessment::scoreMetrics(metrics, rubric);
  const double angle = values.count("entry_angle") ? values.at("entry_angle") : 10.0;
  for (int i = 0; i < 2; ++i) {
    assessment::PierceMetrics p;
    p.time = 12.0 + 9.0 * i;
    p.entryAngleDeg = angle + 4.0 * i;
    p.exitAngleDeg = angle + 8.0;
    p.biteMm = 0.38 + 0.05 * i;
    p.biteWalls = 2.4 + 0.3 * i;
    p.circumferenceDeg = 90.0 + 180.0 * i;
    p.fullThickness = true;
    score.pierces.push_back(p);
  }
  return score;
}

// Ana's first stitch as the opened vessel shows it: both bites on the back wall, 21° apart and
// too wide, and a tear the wall cannot place
assessment::AttemptScore withFlawedEndProduct(assessment::AttemptScore score) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int i = 0; i < 2 && i < int(score.pierces.size()); ++i) {
    assessment::PierceMetrics& p = score.pierces[std::size_t(i)];
    p.entry = 2 * i;
    p.exit = 2 * i + 1;
    p.vessel = 0;
    p.object = 0;
    p.end = i;
    p.circumferenceDeg = 176.0 + 21.0 * i;
    p.backWall = true;
  }
  using K = assessment::EndProductErrorKind;
  score.endProduct = {
      {K::BackWallStitch, 0, 0, -1, 176.0, nan, nan},   {K::WideBite, 0, 0, -1, 176.0, 3.8, 3.0},
      {K::BackWallStitch, 0, 1, -1, 197.0, nan, nan},   {K::WideBite, 0, 1, -1, 197.0, 4.1, 3.0},
      {K::ObliqueStitch, 0, -1, -1, 186.5, 21.0, 15.0}, {K::WallTear, -1, -1, 5, nan, 3.0, nan}};
  return score;
}

bool fillDemoHistory(assessment::HistoryDatabase& db, qint64& instructor) {
  db.setPasswordIterations(1000);
  assessment::PeopleStore people(db);
  const auto grey = people.addInstructor(QStringLiteral("Dr. Grey"), QStringLiteral("demo password"));
  const auto ana = people.addTrainee(QStringLiteral("Ana Ruiz"), QStringLiteral("Residents 2026"));
  const auto ben = people.addTrainee(QStringLiteral("Ben Okafor"), QStringLiteral("Residents 2026"));
  const auto chloe = people.addTrainee(QStringLiteral("Chloé Martin"), QStringLiteral("Fellows"));
  if (!grey || !ana || !ben || !chloe) return false;
  instructor = *grey;

  const QDir rubrics(QDir(lesson::lessonsDirectory()).filePath(QStringLiteral("../rubrics")));
  const auto rubric = [&](const char* id) -> std::optional<assessment::Rubric> {
    auto loaded = assessment::loadRubric(rubrics.filePath(QString::fromLatin1(id) + QStringLiteral(".json")).toStdString());
    if (auto* r = std::get_if<assessment::Rubric>(&loaded)) return *r;
    return std::nullopt;
  };
  const auto orientation = rubric("01_orientation");
  const auto entry = rubric("02_needle_entry");
  const auto stitch = rubric("03_single_stitch");
  if (!orientation || !entry || !stitch) return false;

  assessment::AttemptStore attempts(db);
  assessment::ScoreStore scores(db);
  const auto add = [&](qint64 who, const assessment::Rubric& r, AttemptMode mode,
                       const std::map<std::string, double>& values) {
    const auto id = attempts.begin(who, QString::fromStdString(r.id), mode);
    return id && scores.finish(*id, demoScore(r, values), {});
  };
  bool ok = true;
  // Ana improves steadily at needle entry and becomes proficient
  const double anaAngles[] = {42, 33, 24, 18, 12, 9};
  const double anaTimes[] = {170, 140, 115, 95, 80, 70};
  const double anaBites[] = {4.4, 3.9, 3.4, 3.1, 2.7, 2.6};
  ok = ok && add(*ana, *orientation, AttemptMode::Test, {{"time", 70}, {"path_length", 95}});
  for (int i = 0; i < 6; ++i) {
    ok = ok && add(*ana, *entry, i < 2 ? AttemptMode::Learn : AttemptMode::Test,
                   {{"entry_angle", anaAngles[i]}, {"time", anaTimes[i]}, {"bite_walls", anaBites[i]}});
  }
  if (const auto id =
          attempts.begin(*ana, QString::fromStdString(stitch->id), AttemptMode::Learn)) {
    ok = ok &&
         scores.finish(*id,
                       withFlawedEndProduct(demoScore(
                           *stitch, {{"entry_angle", 28}, {"time", 150}, {"bite_walls", 3.8}})),
                       {});
  } else {
    ok = false;
  }
  // Ben passes orientation, struggles with entry
  ok = ok && add(*ben, *orientation, AttemptMode::Test, {{"time", 160}, {"path_length", 210}});
  ok = ok && add(*ben, *orientation, AttemptMode::Test, {{"time", 85}, {"path_length", 120}});
  ok = ok && add(*ben, *entry, AttemptMode::Learn, {{"entry_angle", 38}, {"time", 160}, {"bite_walls", 1.2}});
  ok = ok && add(*ben, *entry, AttemptMode::Test, {{"entry_angle", 31}, {"time", 130}, {"bite_walls", 1.5}});
  // Chloé, a fellow, is through the single stitch
  ok = ok && add(*chloe, *entry, AttemptMode::Test, {{"entry_angle", 8}, {"time", 55}});
  ok = ok && add(*chloe, *entry, AttemptMode::Test, {{"entry_angle", 6}, {"time", 48}});
  ok = ok && add(*chloe, *stitch, AttemptMode::Test, {{"entry_angle", 14}, {"time", 85}, {"bite_symmetry", 0.08}});
  ok = ok && add(*chloe, *stitch, AttemptMode::Test, {{"entry_angle", 9}, {"time", 70}});
  return ok;
}

// grab() renders the widget itself, so only pending layouts and resizes need to run
bool saveReviewShot(QWidget& widget, const QString& file, QStringList& written, const ScreenInspector& inspect) {
  QCoreApplication::sendPostedEvents();
  QCoreApplication::processEvents();
  if (inspect) inspect(QFileInfo(file).fileName(), widget);
  if (!widget.grab().save(file)) return false;
  written << file;
  return true;
}

}  // namespace

QStringList writeReviewScreenshots(const QString& directory, const ScreenInspector& inspect) {
  QTemporaryDir temp;
  assessment::HistoryDatabase db;
  qint64 instructor = 0;
  if (!temp.isValid() || !db.open(temp.filePath(QStringLiteral("demo.sqlite"))).ok() ||
      !fillDemoHistory(db, instructor) || !QDir().mkpath(directory)) {
    return {};
  }
  QStringList written;
  {
    ReviewPage page(db, {instructor, assessment::Role::Instructor});
    page.resize(1280, 800);
    page.show();
    const QDir out(directory);
    const qint64 ana = page.shownTrainees().value(0).id;
    if (!saveReviewShot(page, out.filePath(QStringLiteral("review-grid.png")), written, inspect)) return {};
    page.showTrainee(ana, QStringLiteral("02_needle_entry"));
    if (!saveReviewShot(page, out.filePath(QStringLiteral("review-history.png")), written, inspect)) return {};
    const auto attempts = assessment::AttemptStore(db).list({instructor, assessment::Role::Instructor}, ana);
    if (attempts.size() > 2) {
      assessment::AnnotationStore(db).add({instructor, assessment::Role::Instructor}, attempts[2].id,
                  QStringLiteral("Better: the needle now enters almost perpendicular. Watch the bite length."));
      page.showAttempt(attempts[2].id);
      if (!saveReviewShot(page, out.filePath(QStringLiteral("review-attempt.png")), written, inspect)) return {};
    }
    // Ana's stitch, its end product opened
    if (!attempts.isEmpty()) {
      page.showAttempt(attempts.back().id);
      if (auto* tabs = page.detailView()->findChild<QTabWidget*>())
        tabs->setCurrentWidget(page.detailView()->endProductPanel());
      if (!saveReviewShot(page, out.filePath(QStringLiteral("review-end-product.png")), written,
                          inspect))
        return {};
    }
  }
  return written;
}

}  // namespace microsim::gui
