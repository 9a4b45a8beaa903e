#include "gui/review/review_data.h"

#include "lesson/lesson.h"
#include "microsim/assessment/storage/score_store.h"

#include <QLocale>
#include <QSet>

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

namespace microsim::gui {

using assessment::AttemptStatus;
using assessment::AttemptSummary;

ReviewCatalog::ReviewCatalog(const QString& lessonsDirectory) {
  const QString language = QLocale().name().left(2);
  for (const lesson::Lesson& l : lesson::loadLessons(lessonsDirectory)) {
    lessons_.push_back({l.id, l.title.in(language), l.scenePath, l.rubricPath});
    auto loaded = assessment::loadRubric(l.rubricPath.toStdString());
    if (auto* r = std::get_if<assessment::Rubric>(&loaded)) rubrics_.emplace(l.id, std::move(*r));
  }
}

QList<ReviewLesson> ReviewCatalog::lessons(const QList<AttemptSummary>& attempts) const {
  QList<ReviewLesson> out;
  QSet<QString> known;
  for (const ReviewLesson& l : lessons_) {
    out << l;
    known.insert(l.id);
  }
  // lessons no longer shipped still have history
  QStringList extra;
  for (const AttemptSummary& a : attempts) {
    if (!known.contains(a.lesson)) {
      known.insert(a.lesson);
      extra << a.lesson;
    }
  }
  extra.sort();
  for (const QString& id : extra) out << ReviewLesson{id, id, {}, {}};
  return out;
}

const ReviewLesson* ReviewCatalog::lesson(const QString& id) const {
  auto it = std::find_if(lessons_.begin(), lessons_.end(), [&](const ReviewLesson& l) { return l.id == id; });
  return it == lessons_.end() ? nullptr : &*it;
}

const assessment::Rubric* ReviewCatalog::rubric(const QString& lessonId) const {
  auto it = rubrics_.find(lessonId);
  return it == rubrics_.end() ? nullptr : &it->second;
}

std::vector<GridRow> buildGrid(const QList<assessment::Trainee>& people, const QList<AttemptSummary>& attempts,
                               const ReviewCatalog& catalog, const QString& group) {
  std::vector<GridRow> rows;
  for (const assessment::Trainee& person : people) {
    if (!group.isEmpty() && person.group != group) continue;
    GridRow row{person, {}};
    for (const AttemptSummary& a : attempts) {
      if (a.traineeId != person.id) continue;
      GridCell& cell = row.cells[a.lesson];
      ++cell.attempts;
      if (a.status == AttemptStatus::Abandoned) ++cell.abandoned;
      if (a.status != AttemptStatus::Finished || !a.score) continue;
      ++cell.finished;
      cell.best = cell.best ? std::max(*cell.best, *a.score) : *a.score;
    }
    for (auto it = row.cells.begin(); it != row.cells.end(); ++it)
      it.value().status = lessonStatus(attempts, person.id, it.key(), catalog.rubric(it.key()));
    rows.push_back(std::move(row));
  }
  return rows;
}

QList<AttemptSummary> finishedAttempts(const QList<AttemptSummary>& attempts, qint64 traineeId,
                                       const QString& lesson) {
  QList<AttemptSummary> out;
  for (const AttemptSummary& a : attempts) {
    if (a.traineeId == traineeId && a.status == AttemptStatus::Finished && a.score &&
        (lesson.isEmpty() || a.lesson == lesson)) {
      out << a;
    }
  }
  return out;
}

std::optional<TargetBand> targetBand(const assessment::Rubric& rubric, const QString& key) {
  const std::string k = key.toStdString();
  for (const assessment::RubricMetric& m : rubric.metrics) {
    if (m.key != k) continue;
    switch (m.bad) {
      case assessment::BadSide::Above:
        return TargetBand{-std::numeric_limits<double>::infinity(), m.target + m.tolerance};
      case assessment::BadSide::Below:
        return TargetBand{m.target - m.tolerance, std::numeric_limits<double>::infinity()};
      case assessment::BadSide::Both: return TargetBand{m.target - m.tolerance, m.target + m.tolerance};
    }
  }
  return std::nullopt;
}

QStringList keyMetrics() {
  return {QStringLiteral("entry_angle"), QStringLiteral("bite_walls"), QStringLiteral("time"),
          QStringLiteral("path_length")};
}

std::optional<double> metricValue(const QList<assessment::StoredMetric>& metrics, const QString& key) {
  for (const assessment::StoredMetric& m : metrics) {
    if (m.key == key && !std::isnan(m.value)) return m.value;
  }
  return std::nullopt;
}

std::vector<PierceRow> pierceRows(const QList<assessment::StoredPierceValue>& values) {
  std::map<int, PierceRow> byPierce;
  for (const assessment::StoredPierceValue& v : values) {
    PierceRow& row = byPierce[v.pierce];
    row.pierce = v.pierce;
    row.values.insert(v.key, v.value);
  }
  std::vector<PierceRow> rows;
  rows.reserve(byPierce.size());
  for (auto& [index, row] : byPierce) rows.push_back(std::move(row));
  return rows;
}

OpenedVessel openedVessel(const assessment::AttemptDetail& detail) {
  OpenedVessel v;
  v.passages = assessment::storedPassages(detail.pierces);
  v.stitches = assessment::stitchMetrics(v.passages);
  v.errors.assign(detail.endProduct.errors.begin(), detail.endProduct.errors.end());
  return v;
}

}  // namespace microsim::gui
