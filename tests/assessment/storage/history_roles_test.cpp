// Roles, stored scores and hostile input, on SQLite and (when a server is given) PostgreSQL.
#include "microsim/assessment/scoring/score.h"
#include "microsim/assessment/storage/annotation_store.h"
#include "microsim/assessment/storage/attempt_detail.h"
#include "microsim/assessment/storage/attempt_store.h"
#include "microsim/assessment/storage/attempts_csv.h"
#include "microsim/assessment/storage/history_database.h"
#include "microsim/assessment/storage/people_store.h"
#include "microsim/assessment/storage/score_store.h"

#include "assessment/storage/history_backend.h"

#include <QBuffer>
#include <QSqlError>
#include <QSqlQuery>

#include <cmath>
#include <map>
#include <limits>
#include <utility>
#include <vector>

namespace microsim::assessment {
namespace {

using testing::HistoryBackend;

AttemptScore sampleScore(double value) {
  AttemptScore s;
  s.score = value;
  s.passed = value >= 70;
  s.rubricId = "anastomosis";
  s.rubricVersion = 3;
  s.metrics.push_back({"entry_angle", 12.5, "deg", 0, 15, 2, 1.0, ""});
  s.metrics.push_back({"path_length", std::numeric_limits<double>::quiet_NaN(), "mm", 300, 100, 1, 0.0,
                       "path_length.missing"});
  s.neverEvents = {"suture_break", "tear"};
  PierceMetrics p;
  p.entry = 0;
  p.exit = 1;
  p.time = 4.25;
  p.vessel = 0;
  p.entryAngleDeg = 8.0;
  p.exitAngleDeg = std::numeric_limits<double>::quiet_NaN();
  p.biteMm = 0.3;
  p.fullThickness = true;
  s.pierces.push_back(p);
  return s;
}

class HistoryRoles : public HistoryBackend {
 protected:
  void SetUp() override {
    HistoryBackend::SetUp();
    if (IsSkipped() || HasFatalFailure()) return;
    openInto(db_);
    ana_ = people_.addTrainee(QStringLiteral("Ana"), QStringLiteral("PGY-2")).value_or(0);
    ben_ = people_.addTrainee(QStringLiteral("Ben")).value_or(0);
    ines_ = people_.addInstructor(QStringLiteral("Ines"), QStringLiteral("correct horse")).value_or(0);
    ASSERT_TRUE(ana_ && ben_ && ines_);
    anaAttempt_ = attempts_.begin(ana_, QStringLiteral("01_bite"), AttemptMode::Test).value_or(0);
    benAttempt_ = attempts_.begin(ben_, QStringLiteral("01_bite"), AttemptMode::Learn).value_or(0);
    ASSERT_TRUE(anaAttempt_ && benAttempt_);
    ASSERT_TRUE(scores_.finish(anaAttempt_, sampleScore(82), QByteArray("MSREC\0\x01\x02", 8)));
    ASSERT_TRUE(scores_.finish(benAttempt_, sampleScore(41), {}));
  }

  /// Ben's new test attempt finished with sampleScore(score) and these end-product errors; its
  /// id, 0 when it could not be stored.
  qint64 benScoredWithErrors(double score, std::vector<EndProductError> errors) {
    AttemptScore s = sampleScore(score);
    s.endProduct = std::move(errors);
    const qint64 id =
        attempts_.begin(ben_, QStringLiteral("03_stitch"), AttemptMode::Test).value_or(0);
    EXPECT_NE(id, 0);
    const bool stored = id != 0 && scores_.finish(id, s, {});
    EXPECT_TRUE(stored) << scores_.lastError().driverMessage.toStdString();
    return stored ? id : 0;
  }

  HistoryDatabase db_;
  PeopleStore people_{db_};
  AttemptStore attempts_{db_};
  ScoreStore scores_{db_};
  AnnotationStore notes_{db_};
  qint64 ana_ = 0, ben_ = 0, ines_ = 0, anaAttempt_ = 0, benAttempt_ = 0;
};

TEST_P(HistoryRoles, TraineeSeesOnlyOwnAttempts) {
  const Viewer ana{ana_, Role::Trainee};
  const QList<AttemptSummary> own = attempts_.list(ana);
  ASSERT_EQ(own.size(), 1);
  EXPECT_EQ(own[0].id, anaAttempt_);
  EXPECT_EQ(own[0].status, AttemptStatus::Finished);
  EXPECT_EQ(own[0].mode, AttemptMode::Test);
  ASSERT_TRUE(own[0].score.has_value());
  EXPECT_DOUBLE_EQ(*own[0].score, 82.0);
  EXPECT_TRUE(own[0].passed);
  EXPECT_EQ(own[0].rubricId.toStdString(), "anastomosis");
  EXPECT_EQ(own[0].rubricVersion, 3);

  // another trainee's list or attempt is refused, not silently empty
  EXPECT_TRUE(attempts_.list(ana, ben_).isEmpty());
  EXPECT_EQ(attempts_.lastError().error, HistoryError::Forbidden);
  HistoryStatus status;
  EXPECT_FALSE(readAttemptDetail(db_, ana, benAttempt_, &status).has_value());
  EXPECT_EQ(status.error, HistoryError::Forbidden);
  EXPECT_TRUE(readAttemptDetail(db_, ana, anaAttempt_).has_value());
}

TEST_P(HistoryRoles, TraineeCannotClaimInstructorRoleNorAnnotate) {
  EXPECT_TRUE(attempts_.list({ana_, Role::Instructor}).isEmpty());
  EXPECT_EQ(attempts_.lastError().error, HistoryError::Forbidden);
  EXPECT_FALSE(notes_.add({ana_, Role::Trainee}, anaAttempt_, QStringLiteral("great")).has_value());
  EXPECT_EQ(notes_.lastError().error, HistoryError::Forbidden);
  EXPECT_FALSE(notes_.add({ana_, Role::Instructor}, anaAttempt_, QStringLiteral("great")).has_value());
  EXPECT_TRUE(attempts_.list({999999, Role::Instructor}).isEmpty());
  EXPECT_EQ(attempts_.lastError().error, HistoryError::Forbidden);
}

TEST_P(HistoryRoles, InstructorSeesAllAndAnnotates) {
  const Viewer ines{ines_, Role::Instructor};
  EXPECT_EQ(attempts_.list(ines).size(), 2);
  EXPECT_EQ(attempts_.list(ines, ben_).size(), 1);
  const auto note = notes_.add(ines, benAttempt_, QStringLiteral("Bites too shallow at 3 o'clock."));
  ASSERT_TRUE(note.has_value());
  const auto detail = readAttemptDetail(db_, ines, benAttempt_);
  ASSERT_TRUE(detail.has_value());
  ASSERT_EQ(detail->annotations.size(), 1);
  EXPECT_EQ(detail->annotations[0].note.toStdString(), "Bites too shallow at 3 o'clock.");
  EXPECT_EQ(detail->annotations[0].authorName.toStdString(), "Ines");
  // the trainee reads the instructor's note on their own attempt
  const auto seen = readAttemptDetail(db_, {ben_, Role::Trainee}, benAttempt_);
  ASSERT_TRUE(seen.has_value());
  EXPECT_EQ(seen->annotations.size(), 1);
}

TEST_P(HistoryRoles, FinishStoresScoreMetricsPiercesAndRecordingTogether) {
  const auto d = readAttemptDetail(db_, {ines_, Role::Instructor}, anaAttempt_);
  ASSERT_TRUE(d.has_value());
  ASSERT_EQ(d->metrics.size(), 2);
  EXPECT_EQ(d->metrics[0].key.toStdString(), "entry_angle");
  EXPECT_DOUBLE_EQ(d->metrics[0].value, 12.5);
  EXPECT_EQ(d->metrics[0].unit.toStdString(), "deg");
  EXPECT_DOUBLE_EQ(d->metrics[0].tolerance, 15);
  EXPECT_DOUBLE_EQ(d->metrics[0].weight, 2);
  EXPECT_DOUBLE_EQ(d->metrics[0].points, 1.0);
  EXPECT_TRUE(std::isnan(d->metrics[1].value));
  EXPECT_EQ(d->metrics[1].feedback.toStdString(), "path_length.missing");
  EXPECT_EQ(d->neverEvents, (QStringList{QStringLiteral("suture_break"), QStringLiteral("tear")}));
  EXPECT_EQ(d->recording, QByteArray("MSREC\0\x01\x02", 8));

  std::map<std::string, double> pierce;
  for (const StoredPierceValue& v : d->pierces) {
    EXPECT_EQ(v.pierce, 0);
    pierce[v.key.toStdString()] = v.value;
  }
  EXPECT_DOUBLE_EQ(pierce.at("entry_angle_deg"), 8.0);
  EXPECT_DOUBLE_EQ(pierce.at("time_s"), 4.25);
  EXPECT_DOUBLE_EQ(pierce.at("full_thickness"), 1.0);
  EXPECT_TRUE(std::isnan(pierce.at("exit_angle_deg")));
}

TEST_P(HistoryRoles, StoredScoreCannotChangeThroughApiOrSql) {
  // a second finish is refused and changes nothing
  EXPECT_FALSE(scores_.finish(anaAttempt_, sampleScore(100), QByteArray("forged")));
  EXPECT_EQ(scores_.lastError().error, HistoryError::NotInProgress);
  const auto d = readAttemptDetail(db_, {ana_, Role::Trainee}, anaAttempt_);
  ASSERT_TRUE(d && d->summary.score);
  EXPECT_DOUBLE_EQ(*d->summary.score, 82.0);
  EXPECT_EQ(d->recording, QByteArray("MSREC\0\x01\x02", 8));

  // the triggers refuse even raw SQL on the connection
  QSqlQuery q(db_.connection());
  EXPECT_FALSE(q.exec(QStringLiteral("UPDATE scores SET score = 100")));
  EXPECT_FALSE(q.exec(QStringLiteral("UPDATE score_metrics SET points = 1")));
  EXPECT_FALSE(q.exec(QStringLiteral("UPDATE recordings SET data = data")));
  EXPECT_FALSE(q.exec(QStringLiteral("UPDATE attempts SET status = 'in_progress' WHERE status = 'finished'")));
  q.prepare(QStringLiteral("INSERT INTO score_metrics (attempt_id, position, metric, value, unit, target, "
                           "tolerance, weight, points, feedback) VALUES (?, 9, 'bonus', 1, '', 0, 0, 100, 1, '')"));
  q.addBindValue(anaAttempt_);
  EXPECT_FALSE(q.exec());
  ASSERT_TRUE(q.exec(QStringLiteral("SELECT score FROM scores ORDER BY attempt_id")) && q.next());
  EXPECT_DOUBLE_EQ(q.value(0).toDouble(), 82.0);
}

TEST_P(HistoryRoles, AbandonMarksOnlyAnAttemptInProgressAndIsNeverScored) {
  const qint64 open = attempts_.begin(ana_, QStringLiteral("03_stitch"), AttemptMode::Test).value_or(0);
  ASSERT_NE(open, 0);
  ASSERT_TRUE(attempts_.abandon(open)) << attempts_.lastError().driverMessage.toStdString();
  const auto abandoned = attempts_.summary({ana_, Role::Trainee}, open);
  ASSERT_TRUE(abandoned.has_value());
  EXPECT_EQ(abandoned->status, AttemptStatus::Abandoned);
  EXPECT_TRUE(abandoned->finished.isValid());
  EXPECT_FALSE(abandoned->score.has_value());

  // neither abandoned twice, nor a finished attempt, nor one that does not exist
  EXPECT_FALSE(attempts_.abandon(open));
  EXPECT_EQ(attempts_.lastError().error, HistoryError::NotInProgress);
  EXPECT_FALSE(attempts_.abandon(anaAttempt_));
  EXPECT_EQ(attempts_.lastError().error, HistoryError::NotInProgress);
  EXPECT_FALSE(attempts_.abandon(987654));
  EXPECT_EQ(attempts_.lastError().error, HistoryError::NotFound);

  // an abandoned attempt takes no score, through the store or raw SQL
  EXPECT_FALSE(scores_.finish(open, sampleScore(90), {}));
  EXPECT_EQ(scores_.lastError().error, HistoryError::NotInProgress);
  QSqlQuery q(db_.connection());
  q.prepare(QStringLiteral("INSERT INTO scores (attempt_id, score, passed, rubric_id, rubric_version) "
                           "VALUES (?, 90, 1, 'r', 1)"));
  q.addBindValue(open);
  EXPECT_FALSE(q.exec());
  EXPECT_EQ(attempts_.summary({ana_, Role::Trainee}, open)->status, AttemptStatus::Abandoned);
}

TEST_P(HistoryRoles, CsvExportNamesEveryStatus) {
  const qint64 abandoned = attempts_.begin(ben_, QStringLiteral("01_bite"), AttemptMode::Test).value_or(0);
  const qint64 open = attempts_.begin(ben_, QStringLiteral("01_bite"), AttemptMode::Test).value_or(0);
  ASSERT_TRUE(abandoned && open);
  ASSERT_TRUE(attempts_.abandon(abandoned));
  QBuffer csv;
  csv.open(QIODevice::WriteOnly);
  ASSERT_TRUE(exportAttemptsCsv(db_, {ben_, Role::Trainee}, csv).ok());
  const QStringList records = QString::fromUtf8(csv.data()).split(QStringLiteral("\r\n"));
  ASSERT_EQ(records.size(), 5);
  EXPECT_TRUE(records[1].contains(QStringLiteral(",learn,finished,"))) << records[1].toStdString();
  EXPECT_TRUE(records[2].startsWith(QStringLiteral("%1,Ben,,01_bite,test,abandoned,").arg(abandoned)))
      << records[2].toStdString();
  EXPECT_TRUE(records[3].startsWith(QStringLiteral("%1,Ben,,01_bite,test,in_progress,").arg(open)))
      << records[3].toStdString();
}

TEST_P(HistoryRoles, InstructorPasswordIsHashedAndChecked) {
  EXPECT_EQ(people_.verifyInstructor(QStringLiteral("Ines"), QStringLiteral("correct horse")), ines_);
  EXPECT_FALSE(people_.verifyInstructor(QStringLiteral("Ines"), QStringLiteral("correct horsE")).has_value());
  EXPECT_EQ(people_.lastError().error, HistoryError::WrongPassword);
  EXPECT_FALSE(people_.verifyInstructor(QStringLiteral("Ana"), QStringLiteral("correct horse")).has_value());
  EXPECT_FALSE(people_.verifyInstructor(QStringLiteral("Nobody"), QStringLiteral("correct horse")).has_value());
  EXPECT_FALSE(people_.addInstructor(QStringLiteral("Short"), QStringLiteral("1234567")).has_value());
  EXPECT_EQ(people_.lastError().error, HistoryError::InvalidInput);

  QSqlQuery q(db_.connection());
  ASSERT_TRUE(q.exec(QStringLiteral("SELECT algorithm, iterations, salt, hash FROM instructor_passwords")) && q.next());
  EXPECT_EQ(q.value(0).toString().toStdString(), "pbkdf2-sha256");
  EXPECT_EQ(q.value(1).toInt(), 1000);
  EXPECT_EQ(q.value(2).toByteArray().size(), 16);
  EXPECT_EQ(q.value(3).toByteArray().size(), 32);
  EXPECT_FALSE(q.value(3).toByteArray().contains("correct horse"));
}

// the app's first-run path may make an instructor only while there is none
TEST_P(HistoryRoles, FirstInstructorOnlyWhileThereIsNone) {
  EXPECT_FALSE(people_.addFirstInstructor(QStringLiteral("Mallory"), QStringLiteral("long enough")).has_value());
  EXPECT_EQ(people_.lastError().error, HistoryError::Forbidden);
  EXPECT_FALSE(people_.verifyInstructor(QStringLiteral("Mallory"), QStringLiteral("long enough")).has_value());

  // a history whose only people are trainees (Ines removed; her password row goes with her)
  QSqlQuery q(db_.connection());
  ASSERT_TRUE(q.exec(QStringLiteral("DELETE FROM trainees WHERE role = 'instructor'"))) << q.lastError().text().toStdString();
  EXPECT_FALSE(people_.addFirstInstructor(QStringLiteral("Ines"), QStringLiteral("short")).has_value());
  EXPECT_EQ(people_.lastError().error, HistoryError::InvalidInput);
  const std::optional<qint64> first = people_.addFirstInstructor(QStringLiteral("Ines"), QStringLiteral("correct horse"));
  ASSERT_TRUE(first.has_value()) << people_.lastError().driverMessage.toStdString();
  EXPECT_EQ(people_.verifyInstructor(QStringLiteral("Ines"), QStringLiteral("correct horse")), first);
  EXPECT_FALSE(people_.addFirstInstructor(QStringLiteral("Ivo"), QStringLiteral("correct horse")).has_value());
  EXPECT_EQ(people_.lastError().error, HistoryError::Forbidden);
  // an instructor adds the next ones through addInstructor
  EXPECT_TRUE(people_.addInstructor(QStringLiteral("Ivo"), QStringLiteral("correct horse")).has_value());
}

TEST_P(HistoryRoles, DuplicateAndEmptyNamesAreRefused) {
  EXPECT_FALSE(people_.addTrainee(QStringLiteral("Ana")).has_value());
  EXPECT_EQ(people_.lastError().error, HistoryError::NameTaken);
  EXPECT_FALSE(people_.addTrainee(QStringLiteral("   ")).has_value());
  EXPECT_EQ(people_.lastError().error, HistoryError::InvalidInput);
  EXPECT_FALSE(attempts_.begin(424242, QStringLiteral("x"), AttemptMode::Learn).has_value());
  EXPECT_EQ(attempts_.lastError().error, HistoryError::NotFound);
}

TEST_P(HistoryRoles, SqlInjectionThroughNamesAndNotesIsInert) {
  const QString evil = QStringLiteral("x'); DROP TABLE attempts;--");
  const QString evilGroup = QStringLiteral("g\"; DELETE FROM trainees; --");
  const QString evilNote = QStringLiteral("'; UPDATE scores SET score = 100; --\n\u00e9\u4e2d");
  const auto id = people_.addTrainee(evil, evilGroup);
  ASSERT_TRUE(id.has_value());
  const auto attemptId = attempts_.begin(*id, evil, AttemptMode::Learn);
  ASSERT_TRUE(attemptId.has_value());
  ASSERT_TRUE(notes_.add({ines_, Role::Instructor}, *attemptId, evilNote).has_value());

  const auto person = people_.person(*id);
  ASSERT_TRUE(person.has_value());
  EXPECT_EQ(person->name, evil);
  EXPECT_EQ(person->group, evilGroup);
  const auto d = readAttemptDetail(db_, {ines_, Role::Instructor}, *attemptId);
  ASSERT_TRUE(d.has_value());
  EXPECT_EQ(d->summary.lesson, evil);
  ASSERT_EQ(d->annotations.size(), 1);
  EXPECT_EQ(d->annotations[0].note, evilNote);
  EXPECT_EQ(people_.trainees().size(), 4);
  EXPECT_EQ(attempts_.list({ines_, Role::Instructor}).size(), 3);
  const auto ana = readAttemptDetail(db_, {ana_, Role::Trainee}, anaAttempt_);
  ASSERT_TRUE(ana && ana->summary.score);
  EXPECT_DOUBLE_EQ(*ana->summary.score, 82.0);
}

TEST_P(HistoryRoles, CsvExportQuotesAndFollowsRoles) {
  ASSERT_TRUE(people_.addTrainee(QStringLiteral("Doe, \"JD\"\nJohn")).has_value());
  const auto doe = people_.trainees();
  qint64 doeId = 0;
  for (const Trainee& t : doe)
    if (t.name.startsWith(QLatin1String("Doe"))) doeId = t.id;
  ASSERT_TRUE(attempts_.begin(doeId, QStringLiteral("02_stitch"), AttemptMode::Learn).has_value());

  QBuffer all;
  all.open(QIODevice::WriteOnly);
  ASSERT_TRUE(exportAttemptsCsv(db_, {ines_, Role::Instructor}, all).ok());
  const QString text = QString::fromUtf8(all.data());
  const QStringList records = text.split(QStringLiteral("\r\n"));
  ASSERT_EQ(records.size(), 5);  // header, three attempts, and the empty rest after the last CRLF
  EXPECT_EQ(records[0].toStdString(),
            "attempt,trainee,group,lesson,mode,status,started,finished,score,passed,rubric,rubric_"
            "version,"
            "end_product_errors,end_product_kinds");
  EXPECT_TRUE(records[1].startsWith(QStringLiteral("%1,Ana,PGY-2,01_bite,test,finished,").arg(anaAttempt_)));
  // judged and clean: no errors, no kinds
  EXPECT_TRUE(records[1].endsWith(QStringLiteral(",82,1,anastomosis,3,0,")))
      << records[1].toStdString();
  EXPECT_TRUE(records[3].contains(QStringLiteral(",\"Doe, \"\"JD\"\"\nJohn\",,02_stitch,learn,in_progress,")));
  EXPECT_TRUE(records[4].isEmpty());

  QBuffer own;
  own.open(QIODevice::WriteOnly);
  ASSERT_TRUE(exportAttemptsCsv(db_, {ben_, Role::Trainee}, own).ok());
  EXPECT_EQ(QString::fromUtf8(own.data()).count(QStringLiteral("\r\n")), 2);
  EXPECT_FALSE(own.data().contains("Ana"));
}

// the end product's errors come back as they were scored, NaN as NaN and "none" as −1, are
// refused any change like the rest of a score, and the CSV counts and names them
TEST_P(HistoryRoles, EndProductErrorsAreStoredReadBackAndExported) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const qint64 id =
      benScoredWithErrors(55, {{EndProductErrorKind::BackWallStitch, 0, 1, -1, 182.5, nan, nan},
                               {EndProductErrorKind::WideBite, -1, 0, -1, 10.0, 3.4, 3.0},
                               {EndProductErrorKind::WallTear, -1, -1, 7, nan, 1.0, nan}});
  ASSERT_NE(id, 0);

  const auto d = readAttemptDetail(db_, {ines_, Role::Instructor}, id);
  ASSERT_TRUE(d.has_value());
  ASSERT_TRUE(d->endProduct.judged);
  ASSERT_EQ(d->endProduct.errors.size(), 3);
  const EndProductError& back = d->endProduct.errors[0];
  EXPECT_EQ(back.kind, EndProductErrorKind::BackWallStitch);
  EXPECT_EQ(back.stitch, 0);
  EXPECT_EQ(back.passage, 1);
  EXPECT_EQ(back.event, -1);
  EXPECT_DOUBLE_EQ(back.angleDeg, 182.5);
  EXPECT_TRUE(std::isnan(back.measured) && std::isnan(back.limit));
  EXPECT_EQ(d->endProduct.errors[1].kind, EndProductErrorKind::WideBite);
  EXPECT_DOUBLE_EQ(d->endProduct.errors[1].measured, 3.4);
  EXPECT_DOUBLE_EQ(d->endProduct.errors[1].limit, 3.0);
  EXPECT_EQ(d->endProduct.errors[2].kind, EndProductErrorKind::WallTear);
  EXPECT_EQ(d->endProduct.errors[2].event, 7);
  EXPECT_TRUE(std::isnan(d->endProduct.errors[2].angleDeg));
  // and the passages they refer to come back from the stored pierce values
  const std::vector<PierceMetrics> passages = storedPassages(d->pierces);
  ASSERT_EQ(passages.size(), 1u);
  EXPECT_EQ(passages[0].entry, 0);
  EXPECT_EQ(passages[0].exit, 1);
  EXPECT_EQ(passages[0].vessel, 0);
  EXPECT_DOUBLE_EQ(passages[0].time, 4.25);
  EXPECT_DOUBLE_EQ(passages[0].biteMm, 0.3);
  EXPECT_TRUE(std::isnan(passages[0].exitAngleDeg));
  EXPECT_TRUE(passages[0].fullThickness);
  EXPECT_FALSE(passages[0].backWall);

  // a clean attempt is judged, with no errors; one never scored is not judged
  const auto clean = readAttemptDetail(db_, {ana_, Role::Trainee}, anaAttempt_);
  ASSERT_TRUE(clean.has_value());
  EXPECT_TRUE(clean->endProduct.judged);
  EXPECT_TRUE(clean->endProduct.errors.isEmpty());
  const qint64 open =
      attempts_.begin(ben_, QStringLiteral("03_stitch"), AttemptMode::Test).value_or(0);
  EXPECT_FALSE(
      scores_.endProduct({ben_, Role::Trainee}, open).value_or(StoredEndProduct{true, {}}).judged);
  // nor may a trainee read another's
  EXPECT_FALSE(scores_.endProduct({ana_, Role::Trainee}, id).has_value());
  EXPECT_EQ(scores_.lastError().error, HistoryError::Forbidden);

  QSqlQuery q(db_.connection());
  EXPECT_FALSE(q.exec(QStringLiteral("UPDATE score_end_product SET kind = 'wall_tear'")));
  q.prepare(QStringLiteral(
      "INSERT INTO score_end_product (attempt_id, position, kind) VALUES (?, 9, 'wall_tear')"));
  q.addBindValue(id);
  EXPECT_FALSE(q.exec());

  QBuffer csv;
  csv.open(QIODevice::WriteOnly);
  ASSERT_TRUE(exportAttemptsCsv(db_, {ben_, Role::Trainee}, csv).ok());
  const QStringList records = QString::fromUtf8(csv.data()).split(QStringLiteral("\r\n"));
  ASSERT_EQ(records.size(), 5);  // header, Ben's finished, scored and open attempts, the empty rest
  EXPECT_TRUE(records[2].startsWith(QStringLiteral("%1,").arg(id))) << records[2].toStdString();
  EXPECT_TRUE(records[2].endsWith(QStringLiteral(",3,back_wall_stitch wide_bite wall_tear")))
      << records[2].toStdString();
  // started, then empty: finished, score, passed, rubric, version, count, kinds
  EXPECT_TRUE(records[3].contains(QStringLiteral(",in_progress,"))) << records[3].toStdString();
  EXPECT_TRUE(records[3].endsWith(QStringLiteral("Z,,,,,,,"))) << records[3].toStdString();
}

// the final scene's three (sim/scene/end_state_check.h), located by angle with a measure and
// a limit, come back as they were scored
TEST_P(HistoryRoles, TheFinalScenesLapsesRoundTrip) {
  const std::vector<EndProductError> stored = {
      {EndProductErrorKind::OverTightStitch, -1, -1, -1, 45.5, 0.4, 0.25},
      {EndProductErrorKind::ThreadInLumen, -1, -1, -1, 100.25, 0.2, 0.05},
      {EndProductErrorKind::LargeEdgeOverlap, -1, -1, -1, 210.0, 0.09, 0.05}};
  const qint64 id = benScoredWithErrors(61, stored);
  ASSERT_NE(id, 0);

  const auto d = readAttemptDetail(db_, {ines_, Role::Instructor}, id);
  ASSERT_TRUE(d.has_value());
  ASSERT_TRUE(d->endProduct.judged);
  ASSERT_EQ(d->endProduct.errors.size(), 3);
  for (int i = 0; i < 3; ++i) {
    const EndProductError& want = stored[static_cast<std::size_t>(i)];
    const EndProductError& got = d->endProduct.errors[i];
    EXPECT_EQ(got.kind, want.kind) << i;
    EXPECT_EQ(got.stitch, -1);
    EXPECT_EQ(got.passage, -1);
    EXPECT_EQ(got.event, -1);
    EXPECT_DOUBLE_EQ(got.angleDeg, want.angleDeg);
    EXPECT_DOUBLE_EQ(got.measured, want.measured);
    EXPECT_DOUBLE_EQ(got.limit, want.limit);
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, HistoryRoles, ::testing::Values(Driver::SQLite, Driver::PostgreSQL),
                         testing::backendName);

}  // namespace
}  // namespace microsim::assessment
