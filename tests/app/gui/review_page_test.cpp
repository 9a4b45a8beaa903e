// The review page on a real temporary SQLite history: two trainees with finished attempts
// scored through the scoring API, an instructor signed in with a password.
#include "gui/review/review_page.h"
#include "gui/pages/end_product_panel.h"
#include "gui/pages/sign_in_page.h"
#include "gui/review/attempt_detail_view.h"
#include "gui/review/replay_player.h"
#include "gui/review/review_charts.h"
#include "gui/review/review_data.h"
#include "gui/review/review_text.h"
#include "gui/review/trainee_history_view.h"
#include "gui/simulation_runner.h"
#include "lesson/lesson.h"
#include "microsim/assessment/scoring/score.h"
#include "microsim/assessment/storage/attempt_detail.h"
#include "microsim/assessment/storage/attempt_store.h"
#include "microsim/assessment/storage/people_store.h"
#include "microsim/assessment/storage/score_store.h"
#include "microsim/sim/scene/recording.h"

#include <QBuffer>
#include <QChart>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QLineSeries>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

#include <limits>
#include <utility>
#include <variant>

namespace microsim::gui {
namespace {

using assessment::AttemptMode;
using assessment::AttemptSummary;
using assessment::Role;
using assessment::Viewer;

// RFC 4180 records: quoted fields may hold ',', CRLF and doubled quotes
QList<QStringList> parseCsv(const QString& text) {
  QList<QStringList> records;
  QStringList fields;
  QString field;
  bool quoted = false;
  for (qsizetype i = 0; i < text.size(); ++i) {
    const QChar c = text[i];
    if (quoted) {
      if (c == QLatin1Char('"') && i + 1 < text.size() && text[i + 1] == QLatin1Char('"')) {
        field += c;
        ++i;
      } else if (c == QLatin1Char('"')) {
        quoted = false;
      } else {
        field += c;
      }
    } else if (c == QLatin1Char('"')) {
      quoted = true;
    } else if (c == QLatin1Char(',')) {
      fields << field;
      field.clear();
    } else if (c == QLatin1Char('\r') && i + 1 < text.size() && text[i + 1] == QLatin1Char('\n')) {
      fields << field;
      records << fields;
      fields.clear();
      field.clear();
      ++i;
    } else {
      field += c;
    }
  }
  return records;
}

assessment::Rubric rubric(const QString& lessonId) {
  const QString path = QDir(lesson::lessonsDirectory()).filePath(QStringLiteral("../rubrics/%1.json").arg(lessonId));
  auto loaded = assessment::loadRubric(path.toStdString());
  EXPECT_TRUE(std::holds_alternative<assessment::Rubric>(loaded)) << path.toStdString();
  return std::get<assessment::Rubric>(loaded);
}

// a score from the real scoring API: the given entry angle and time, other metrics ideal
assessment::AttemptScore score(const assessment::Rubric& r, double entryAngle, double time) {
  std::vector<assessment::MetricValue> values;
  for (const assessment::RubricMetric& m : r.metrics) {
    double v = m.target;
    if (m.key == "entry_angle") v = entryAngle;
    if (m.key == "time") v = time;
    values.push_back({m.key, v, std::string(assessment::findMetric(m.key)->unit)});
  }
  assessment::AttemptScore s = assessment::scoreMetrics(values, r);
  assessment::PierceMetrics p;
  p.entryAngleDeg = entryAngle;
  p.exitAngleDeg = 12.0;
  p.biteMm = 0.4;
  p.biteWalls = 2.5;
  p.fullThickness = true;
  s.pierces = {p};
  return s;
}

// the first frames of the shipped stitch recording, as stored bytes
QByteArray shortRecording(std::size_t frames) {
  sim::Recording rec;
  const QString path = QDir(lesson::lessonsDirectory()).filePath(QStringLiteral("../recordings/stitch.msrec"));
  const sim::RecordingStatus status = sim::readRecording(path.toStdString(), rec);
  EXPECT_TRUE(status.ok());
  rec.frames.resize(std::min(frames, rec.frames.size()));
  const std::vector<std::uint8_t> bytes = sim::encodeRecording(rec);
  return QByteArray(reinterpret_cast<const char*>(bytes.data()), qsizetype(bytes.size()));
}

class ReviewPageTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(dir_.isValid());
    history_.setPasswordIterations(1000);
    ASSERT_TRUE(history_.open(dir_.filePath(QStringLiteral("history.sqlite"))).ok());
    instructorId_ = *assessment::PeopleStore(history_).addInstructor(QStringLiteral("Dr Grey"), QStringLiteral("correct horse"));
    ana_ = *assessment::PeopleStore(history_).addTrainee(QStringLiteral("Ana"), QStringLiteral("Tuesday"));
    // a name that needs quoting in CSV
    ben_ = *assessment::PeopleStore(history_).addTrainee(QStringLiteral("Ben \"B\" O'Neil, Jr."), QStringLiteral("Thursday"));

    const assessment::Rubric entry = rubric(QStringLiteral("02_needle_entry"));
    const assessment::Rubric stitch = rubric(QStringLiteral("03_single_stitch"));
    for (const auto& [angle, time] : {std::pair{40.0, 150.0}, {20.0, 90.0}, {5.0, 50.0}}) {
      finish(ana_, QStringLiteral("02_needle_entry"), AttemptMode::Test, score(entry, angle, time));
    }
    // one still in progress: counted in the grid, not plotted
    ASSERT_TRUE(assessment::AttemptStore(history_).begin(ana_, QStringLiteral("02_needle_entry"), AttemptMode::Learn));
    finish(ben_, QStringLiteral("03_single_stitch"), AttemptMode::Learn, score(stitch, 30.0, 60.0));
    finish(ben_, QStringLiteral("03_single_stitch"), AttemptMode::Test, score(stitch, 10.0, 70.0));
  }

  void finish(qint64 trainee, const QString& lesson, AttemptMode mode, const assessment::AttemptScore& s) {
    const std::optional<qint64> id = assessment::AttemptStore(history_).begin(trainee, lesson, mode);
    ASSERT_TRUE(id);
    ASSERT_TRUE(assessment::ScoreStore(history_).finish(*id, s, shortRecording(40)));
  }

  // through the app's sign-in page, as an instructor does it
  Viewer signInInstructor() {
    SignInPage signIn(&history_);
    std::optional<Viewer> viewer;
    QObject::connect(&signIn, &SignInPage::signedIn, [&](const Viewer& v, const QString&) { viewer = v; });
    signIn.findChild<QLineEdit*>(QStringLiteral("instructorName"))->setText(QStringLiteral("Dr Grey"));
    signIn.findChild<QLineEdit*>(QStringLiteral("instructorPassword"))->setText(QStringLiteral("correct horse"));
    signIn.findChild<QPushButton*>(QStringLiteral("instructorSignInButton"))->click();
    EXPECT_TRUE(viewer);
    EXPECT_EQ(viewer.value_or(Viewer{}).userId, instructorId_);
    EXPECT_EQ(viewer.value_or(Viewer{}).role, Role::Instructor);
    return viewer.value_or(Viewer{});
  }

  // the page's CSV export to file `name`, read back as records (the header first)
  QList<QStringList> exportedCsv(ReviewPage& page, const QString& name) {
    const QString path = dir_.filePath(name);
    page.setCsvPath(path);
    EXPECT_TRUE(page.exportCsv()) << page.message().toStdString();
    QFile file(path);
    EXPECT_TRUE(file.open(QIODevice::ReadOnly));
    return parseCsv(QString::fromUtf8(file.readAll()));
  }

  QTemporaryDir dir_;
  assessment::HistoryDatabase history_;
  qint64 instructorId_ = 0;
  qint64 ana_ = 0;
  qint64 ben_ = 0;
};

TEST_F(ReviewPageTest, InstructorCsvRowsMatchTheDatabase) {
  const Viewer instructor = signInInstructor();
  ReviewPage page(history_, instructor);
  page.resize(1200, 800);
  page.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&page));

  const QList<QStringList> records = exportedCsv(page, QStringLiteral("export.csv"));
  const QList<AttemptSummary> stored = assessment::AttemptStore(history_).list(instructor);
  ASSERT_EQ(stored.size(), 6);
  ASSERT_EQ(records.size(), stored.size() + 1);
  const QStringList& header = records[0];
  const auto column = [&](const char* name) { return header.indexOf(QString::fromLatin1(name)); };
  for (int i = 0; i < stored.size(); ++i) {
    const QStringList& row = records[i + 1];
    const AttemptSummary& a = stored[i];
    ASSERT_EQ(row.size(), header.size());
    EXPECT_EQ(row[column("attempt")].toLongLong(), a.id);
    EXPECT_EQ(row[column("trainee")], a.traineeId == ana_ ? QStringLiteral("Ana") : QStringLiteral("Ben \"B\" O'Neil, Jr."));
    EXPECT_EQ(row[column("lesson")], a.lesson);
    if (a.score) {
      EXPECT_NEAR(row[column("score")].toDouble(), *a.score, 1e-6);
      EXPECT_EQ(row[column("passed")], a.passed ? QStringLiteral("1") : QStringLiteral("0"));
    } else {
      EXPECT_TRUE(row[column("score")].isEmpty());
    }
  }
}

TEST_F(ReviewPageTest, GridShowsBestScoreAttemptsAndGroupsFilter) {
  ReviewPage page(history_, signInInstructor());
  ASSERT_EQ(page.shownTrainees().size(), 2);
  EXPECT_EQ(page.grid()->rowCount(), 2);

  // Ana: 4 attempts in lesson 02, best score is the last (5°, 50 s: full points)
  const QList<AttemptSummary> stored = assessment::AttemptStore(history_).list(signInInstructor(), ana_);
  double best = 0;
  for (const AttemptSummary& a : stored) best = std::max(best, a.score.value_or(0.0));
  int lessonColumn = -1;
  for (int c = 0; c < page.grid()->columnCount(); ++c) {
    if (page.lessonChooser()->itemData(c - 2).toString() == QStringLiteral("02_needle_entry")) lessonColumn = c;
  }
  ASSERT_GE(lessonColumn, 2);
  const int anaRow = page.shownTrainees()[0].id == ana_ ? 0 : 1;
  const QString cell = page.grid()->item(anaRow, lessonColumn)->text();
  EXPECT_TRUE(cell.startsWith(QLocale().toString(best, 'f', 0))) << cell.toStdString();
  EXPECT_TRUE(cell.contains(QStringLiteral("(4)"))) << cell.toStdString();
  EXPECT_TRUE(cell.contains(QStringLiteral("✓")));

  page.setGroupFilter(QStringLiteral("Thursday"));
  ASSERT_EQ(page.shownTrainees().size(), 1);
  EXPECT_EQ(page.shownTrainees()[0].id, ben_);
  page.setGroupFilter({});
  EXPECT_EQ(page.shownTrainees().size(), 2);
}

TEST_F(ReviewPageTest, AbandonedAttemptsAreCountedNamedAndExported) {
  assessment::AttemptStore attempts(history_);
  const qint64 gaveUp = attempts.begin(ben_, QStringLiteral("03_single_stitch"), AttemptMode::Test).value_or(0);
  ASSERT_TRUE(attempts.abandon(gaveUp));
  const Viewer instructor = signInInstructor();
  ReviewPage page(history_, instructor);

  // the grid counts it among Ben's attempts and says how many were abandoned
  int lessonColumn = -1;
  for (int c = 0; c < page.grid()->columnCount(); ++c) {
    if (page.lessonChooser()->itemData(c - 2).toString() == QStringLiteral("03_single_stitch")) lessonColumn = c;
  }
  ASSERT_GE(lessonColumn, 2);
  const int benRow = page.shownTrainees()[0].id == ben_ ? 0 : 1;
  const QTableWidgetItem* cell = page.grid()->item(benRow, lessonColumn);
  EXPECT_TRUE(cell->text().contains(QStringLiteral("(3)"))) << cell->text().toStdString();
  EXPECT_TRUE(cell->toolTip().contains(QStringLiteral("2 finished, 1 abandoned"))) << cell->toolTip().toStdString();

  // its own word, apart from a crash's, in the detail, the PDF and the CSV
  EXPECT_EQ(ReviewText::status(assessment::AttemptStatus::Abandoned), QStringLiteral("Abandoned"));
  EXPECT_NE(ReviewText::status(assessment::AttemptStatus::Abandoned),
            ReviewText::status(assessment::AttemptStatus::Interrupted));
  const QList<QStringList> records = exportedCsv(page, QStringLiteral("with-abandoned.csv"));
  ASSERT_FALSE(records.isEmpty());
  const qsizetype status = records[0].indexOf(QStringLiteral("status"));
  bool found = false;
  for (const QStringList& row : records) {
    if (row[0].toLongLong() != gaveUp) continue;
    found = true;
    EXPECT_EQ(row[status], QStringLiteral("abandoned"));
  }
  EXPECT_TRUE(found);
}

TEST_F(ReviewPageTest, ScoreChartHasOnePointPerFinishedAttempt) {
  const Viewer instructor = signInInstructor();
  ReviewPage page(history_, instructor);
  page.showTrainee(ana_, QStringLiteral("02_needle_entry"));

  QLineSeries* series = ReviewCharts::scoreSeries(page.historyView()->scoreChart());
  ASSERT_NE(series, nullptr);
  QList<double> expected;
  for (const AttemptSummary& a : assessment::AttemptStore(history_).list(instructor, ana_)) {
    if (a.status == assessment::AttemptStatus::Finished) expected << *a.score;
  }
  ASSERT_EQ(expected.size(), 3);
  ASSERT_EQ(series->count(), 3);
  for (int i = 0; i < 3; ++i) {
    EXPECT_DOUBLE_EQ(series->at(i).x(), i + 1);
    EXPECT_DOUBLE_EQ(series->at(i).y(), expected[i]);
  }
  // the rubric's pass mark as a line
  bool passLine = false;
  for (QAbstractSeries* s : page.historyView()->scoreChart()->series()) {
    if (s->objectName() == QLatin1String(kPassMarkSeriesName)) {
      passLine = true;
      EXPECT_DOUBLE_EQ(static_cast<QLineSeries*>(s)->at(0).y(), 70.0);
    }
  }
  EXPECT_TRUE(passLine);
  EXPECT_EQ(page.historyView()->attemptsTable()->rowCount(), 3);

  // the entry-angle chart: one value per attempt, above the target band [0, 15]
  QChart* angleChart = nullptr;
  for (QChart* chart : page.historyView()->metricCharts())
    if (chart->objectName() == QStringLiteral("entry_angle")) angleChart = chart;
  ASSERT_NE(angleChart, nullptr);
  QLineSeries* angles = nullptr;
  for (QAbstractSeries* s : angleChart->series()) {
    if (s->objectName() == QLatin1String(kMetricSeriesName)) angles = qobject_cast<QLineSeries*>(s);
  }
  ASSERT_NE(angles, nullptr);
  ASSERT_EQ(angles->count(), 3);
  EXPECT_DOUBLE_EQ(angles->at(0).y(), 40.0);
  EXPECT_DOUBLE_EQ(angles->at(2).y(), 5.0);
}

TEST_F(ReviewPageTest, TraineeSeesOnlyTheirOwnHistory) {
  const Viewer trainee{ben_, Role::Trainee};
  ReviewPage page(history_, trainee);
  ASSERT_EQ(page.shownTrainees().size(), 1);
  EXPECT_EQ(page.shownTrainees()[0].id, ben_);
  EXPECT_EQ(page.grid()->rowCount(), 1);
  EXPECT_EQ(page.traineeChooser()->count(), 1);

  const QList<QStringList> records = exportedCsv(page, QStringLiteral("mine.csv"));
  ASSERT_EQ(records.size(), 3);  // header and Ben's two attempts
  for (int i = 1; i < records.size(); ++i) EXPECT_EQ(records[i][1], QStringLiteral("Ben \"B\" O'Neil, Jr."));

  // a trainee reads their attempt but cannot annotate it
  const QList<AttemptSummary> mine = assessment::AttemptStore(history_).list(trainee);
  page.showAttempt(mine[0].id);
  EXPECT_EQ(page.detailView()->attemptId(), mine[0].id);
  EXPECT_FALSE(page.detailView()->addNoteButton()->isEnabled());
}

TEST_F(ReviewPageTest, AttemptDetailShowsMetricsPiercesAndStoresANote) {
  const Viewer instructor = signInInstructor();
  ReviewPage page(history_, instructor);
  const AttemptSummary first = assessment::AttemptStore(history_).list(instructor, ana_)[0];
  page.showAttempt(first.id);

  AttemptDetailView* detail = page.detailView();
  EXPECT_EQ(detail->metricsTable()->rowCount(), int(rubric(QStringLiteral("02_needle_entry")).metrics.size()));
  ASSERT_EQ(detail->piercesTable()->rowCount(), 1);
  EXPECT_EQ(detail->piercesTable()->item(0, 2)->text(), QLocale().toString(40.0, 'f', 1));  // entry angle

  detail->noteEditor()->setPlainText(QStringLiteral("Enter perpendicular; '); DROP TABLE attempts; --"));
  QTest::mouseClick(detail->addNoteButton(), Qt::LeftButton);
  const std::optional<assessment::AttemptDetail> stored = assessment::readAttemptDetail(history_, instructor, first.id);
  ASSERT_TRUE(stored);
  ASSERT_EQ(stored->annotations.size(), 1);
  EXPECT_EQ(stored->annotations[0].note, QStringLiteral("Enter perpendicular; '); DROP TABLE attempts; --"));
  EXPECT_EQ(detail->annotationsList()->count(), 1);
  EXPECT_EQ(assessment::AttemptStore(history_).list(instructor).size(), 6);
}

TEST_F(ReviewPageTest, ReplayStepsEveryStoredFrame) {
  ReviewPage page(history_, signInInstructor());
  page.resize(1200, 800);
  page.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&page));
  page.showAttempt(assessment::AttemptStore(history_).list(signInInstructor(), ben_)[0].id);
  ASSERT_TRUE(page.detailView()->startReplay());
  ReplayPlayer* player = page.detailView()->replayPlayer();
  ASSERT_NE(player, nullptr);
  EXPECT_EQ(player->frameCount(), 40);
  QSignalSpy done(player, &ReplayPlayer::finished);
  player->skipToEnd();
  ASSERT_TRUE(done.count() > 0 || done.wait(30000));
  EXPECT_EQ(player->framesSent(), 40);
  EXPECT_EQ(player->runner()->steps(), 40);
}

TEST_F(ReviewPageTest, PdfReportIsWritten) {
  ReviewPage page(history_, signInInstructor());
  page.showTrainee(ana_);
  const QString path = dir_.filePath(QStringLiteral("ana.pdf"));
  page.setPdfPath(path);
  ASSERT_TRUE(page.exportPdf()) << page.message().toStdString();
  QFile file(path);
  ASSERT_TRUE(file.open(QIODevice::ReadOnly));
  const QByteArray bytes = file.readAll();
  EXPECT_TRUE(bytes.startsWith("%PDF-"));
  EXPECT_GT(bytes.size(), 2000);
}

// pages and embedded pictures of a PDF, read from its objects' dictionaries (not compressed)
std::pair<int, int> pdfPagesAndImages(const QString& path) {
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly)) return {-1, -1};
  const QByteArray bytes = file.readAll();
  return {int(bytes.count("/Type /Page\n") + bytes.count("/Type /Page\r") +
              bytes.count("/Type /Page ") + bytes.count("/Type /Page/")),
          int(bytes.count("/Subtype /Image"))};
}

// Ana's stitch with two end-product errors: a back-wall catch on its second passage and a
// tear that has no place
assessment::AttemptScore scoreWithEndProductErrors(const assessment::Rubric& r) {
  assessment::AttemptScore s = score(r, 20.0, 80.0);
  assessment::PierceMetrics second = s.pierces[0];
  s.pierces[0].entry = 0;
  s.pierces[0].exit = 1;
  s.pierces[0].vessel = 0;
  s.pierces[0].object = 0;
  s.pierces[0].end = 0;
  s.pierces[0].circumferenceDeg = 170.0;
  second.entry = 2;
  second.exit = 3;
  second.vessel = 0;
  second.object = 0;
  second.end = 1;
  second.circumferenceDeg = 186.0;
  second.backWall = true;
  s.pierces.push_back(second);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  s.endProduct = {{assessment::EndProductErrorKind::BackWallStitch, 0, 1, -1, 186.0, nan, nan},
                  {assessment::EndProductErrorKind::WallTear, -1, -1, 4, nan, 1.0, nan}};
  return s;
}

TEST_F(ReviewPageTest, EndProductErrorsReachTheAttemptViewTheCsvAndThePdf) {
  const Viewer instructor = signInInstructor();
  const QString clean = dir_.filePath(QStringLiteral("clean.pdf"));
  {
    ReviewPage page(history_, instructor);
    page.showTrainee(ana_);
    page.setPdfPath(clean);
    ASSERT_TRUE(page.exportPdf()) << page.message().toStdString();
  }
  finish(ana_, QStringLiteral("03_single_stitch"), AttemptMode::Test,
         scoreWithEndProductErrors(rubric(QStringLiteral("03_single_stitch"))));
  const AttemptSummary flawed = assessment::AttemptStore(history_).list(instructor, ana_).back();

  ReviewPage page(history_, instructor);
  // the attempt view: the stitch rebuilt from the stored passages, both errors listed
  page.showAttempt(flawed.id);
  EndProductPanel* panel = page.detailView()->endProductPanel();
  ASSERT_NE(panel, nullptr);
  ASSERT_EQ(panel->errorTable()->rowCount(), 2);
  EXPECT_EQ(panel->errorTable()->item(0, 1)->text(), QStringLiteral("back-wall stitch"));
  EXPECT_EQ(panel->errorTable()->item(0, 2)->text(), QStringLiteral("stitch 1, pierce 2, at 186°"));
  EXPECT_EQ(panel->errorTable()->item(1, 1)->text(), QStringLiteral("wall tear"));
  EXPECT_EQ(panel->errorTable()->item(1, 2)->text(), QStringLiteral("not located"));
  const OpenedVessel vessel =
      openedVessel(*assessment::readAttemptDetail(history_, instructor, flawed.id));
  ASSERT_EQ(vessel.stitches.size(), 1u);
  EXPECT_EQ(vessel.stitches[0].first, 0);
  EXPECT_EQ(vessel.stitches[0].second, 1);
  EXPECT_FALSE(panel->image().isNull());
  // a clean stored attempt says so
  page.showAttempt(assessment::AttemptStore(history_).list(instructor, ana_)[0].id);
  EXPECT_EQ(panel->summaryLabel()->text(), QStringLiteral("No end-product errors."));

  // the CSV: the old columns in their order, then the count and the kinds
  const QList<QStringList> records = exportedCsv(page, QStringLiteral("errors.csv"));
  ASSERT_GE(records.size(), 2);
  ASSERT_EQ(records[0].size(), 14);
  EXPECT_EQ(records[0][11], QStringLiteral("rubric_version"));
  EXPECT_EQ(records[0][12], QStringLiteral("end_product_errors"));
  EXPECT_EQ(records[0][13], QStringLiteral("end_product_kinds"));
  int checked = 0;
  for (const QStringList& r : records) {
    if (r.size() < 14 || r[0] == QStringLiteral("attempt")) continue;
    if (r[0] == QString::number(flawed.id)) {
      EXPECT_EQ(r[12], QStringLiteral("2"));
      EXPECT_EQ(r[13], QStringLiteral("back_wall_stitch wall_tear"));
    } else if (r[5] == QStringLiteral("finished")) {
      EXPECT_EQ(r[12], QStringLiteral("0"));
      EXPECT_EQ(r[13], QString());
    } else {
      EXPECT_EQ(r[12], QString());
    }
    ++checked;
  }
  EXPECT_EQ(checked, 7);

  // the PDF: a page more, with the opened vessel drawn on it
  page.showTrainee(ana_);
  const QString flawedPdf = dir_.filePath(QStringLiteral("flawed.pdf"));
  page.setPdfPath(flawedPdf);
  ASSERT_TRUE(page.exportPdf()) << page.message().toStdString();
  const auto [cleanPages, cleanImages] = pdfPagesAndImages(clean);
  const auto [flawedPages, flawedImages] = pdfPagesAndImages(flawedPdf);
  EXPECT_GE(cleanPages, 1);
  EXPECT_EQ(cleanImages, 0);
  EXPECT_GT(flawedPages, cleanPages);
  EXPECT_GE(flawedImages, 1);
}

// a full disk (/dev/full: every write fails with ENOSPC): each export says so, naming the
// file and the reason, and does not claim success
TEST_F(ReviewPageTest, ExportsOnAFullDiskReportTheFileAndTheReason) {
  ReviewPage page(history_, signInInstructor());
  page.resize(1200, 800);
  page.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&page));
  page.showTrainee(ana_);
  const QString full = QStringLiteral("/dev/full");
  ASSERT_TRUE(QFileInfo::exists(full) && !QFileInfo(full).isFile()) << "/dev/full is not the device";

  page.setCsvPath(full);
  EXPECT_FALSE(page.exportCsv());
  EXPECT_TRUE(page.message().contains(full)) << page.message().toStdString();
  EXPECT_TRUE(page.message().contains(QStringLiteral("No space left on device"))) << page.message().toStdString();
  EXPECT_FALSE(page.message().contains(QStringLiteral("Exported"))) << page.message().toStdString();

  page.setPdfPath(full);
  EXPECT_FALSE(page.exportPdf());
  EXPECT_TRUE(page.message().contains(full)) << page.message().toStdString();
  EXPECT_TRUE(page.message().contains(QStringLiteral("No space left on device"))) << page.message().toStdString();
  EXPECT_FALSE(page.message().contains(QStringLiteral("Saved"))) << page.message().toStdString();
  // written in place, never replaced (QSaveFile's rename would succeed as root)
  ASSERT_FALSE(QFileInfo(full).isFile()) << "the export put a regular file where the device was; as root restore it: rm /dev/full && mknod -m 666 /dev/full c 1 7";

  // a folder that cannot be created: the reason too, and the page keeps working afterwards
  const QString nowhere = dir_.filePath(QStringLiteral("missing/ana.pdf"));
  page.setPdfPath(nowhere);
  EXPECT_FALSE(page.exportPdf());
  EXPECT_TRUE(page.message().contains(nowhere)) << page.message().toStdString();
  const QString path = dir_.filePath(QStringLiteral("ana.pdf"));
  page.setPdfPath(path);
  EXPECT_TRUE(page.exportPdf()) << page.message().toStdString();
  EXPECT_TRUE(page.message().contains(path)) << page.message().toStdString();
}

}  // namespace
}  // namespace microsim::gui
