#include "microsim/assessment/storage/attempts_csv.h"

#include "microsim/assessment/storage/attempt_store.h"
#include "microsim/assessment/storage/csv.h"
#include "microsim/assessment/storage/people_store.h"
#include "microsim/assessment/storage/score_store.h"

#include "storage/sql_util.h"

#include <QHash>
#include <QLocale>

#include <utility>

namespace microsim::assessment {

namespace {

QString csvNumber(double v) { return QString::number(v, 'g', QLocale::FloatingPointShortest); }

}  // namespace

HistoryStatus exportAttemptsCsv(HistoryDatabase& database, const Viewer& viewer, QIODevice& out) {
  AttemptStore attempts(database);
  const QList<AttemptSummary> rows = attempts.list(viewer);
  if (!attempts.lastError().ok()) return attempts.lastError();
  PeopleStore peopleStore(database);
  QHash<qint64, Trainee> people;
  for (const Trainee& t : peopleStore.trainees()) people.insert(t.id, t);
  if (!peopleStore.lastError().ok()) return peopleStore.lastError();

  QString text = csvRecord(
      {QStringLiteral("attempt"), QStringLiteral("trainee"), QStringLiteral("group"),
       QStringLiteral("lesson"), QStringLiteral("mode"), QStringLiteral("status"),
       QStringLiteral("started"), QStringLiteral("finished"), QStringLiteral("score"),
       QStringLiteral("passed"), QStringLiteral("rubric"), QStringLiteral("rubric_version"),
       QStringLiteral("end_product_errors"), QStringLiteral("end_product_kinds")});
  ScoreStore scores(database);
  for (const AttemptSummary& a : rows) {
    const Trainee who = people.value(a.traineeId);
    const bool scored = a.score.has_value();
    StoredEndProduct endProduct;
    if (scored) {
      std::optional<StoredEndProduct> stored = scores.endProduct(viewer, a.id);
      if (!stored) return scores.lastError();
      endProduct = std::move(*stored);
    }
    QStringList kinds;
    for (const EndProductError& e : endProduct.errors)
      kinds << QString::fromLatin1(endProductErrorKey(e.kind));
    text += csvRecord({QString::number(a.id), who.name, who.group, a.lesson, sql::modeText(a.mode),
                       sql::statusText(a.status), a.started.toString(Qt::ISODateWithMs),
                       a.finished.isValid() ? a.finished.toString(Qt::ISODateWithMs) : QString(),
                       scored ? csvNumber(*a.score) : QString(),
                       scored ? (a.passed ? QStringLiteral("1") : QStringLiteral("0")) : QString(),
                       a.rubricId, scored ? QString::number(a.rubricVersion) : QString(),
                       endProduct.judged ? QString::number(endProduct.errors.size()) : QString(),
                       kinds.join(QLatin1Char(' '))});
  }
  if (out.write(text.toUtf8()) < 0) return {HistoryError::FileError, out.errorString()};
  return {};
}

}  // namespace microsim::assessment
