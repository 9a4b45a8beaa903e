#include "gui/review/review_page.h"

#include "gui/review/attempt_detail_view.h"
#include "gui/review/review_report.h"
#include "gui/review/review_text.h"
#include "gui/review/trainee_history_view.h"
#include "lesson/lesson.h"

#include "microsim/assessment/storage/annotation_store.h"
#include "microsim/assessment/storage/attempt_detail.h"
#include "microsim/assessment/storage/attempt_store.h"
#include "microsim/assessment/storage/people_store.h"
#include "microsim/assessment/storage/score_store.h"

#include <QComboBox>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>

namespace microsim::gui {

using assessment::AttemptSummary;
using assessment::Role;
using assessment::Trainee;

namespace {

constexpr int kFixedColumns = 2;  // name, group

QColor cellColour(const GridCell& cell) {
  if (cell.status == LessonStatus::Proficient) return {140, 205, 140};
  if (cell.status == LessonStatus::Passed) return {200, 235, 200};
  if (cell.finished > 0) return {250, 225, 190};
  return {235, 235, 235};
}

}  // namespace

ReviewPage::ReviewPage(assessment::HistoryDatabase& history, const assessment::Viewer& viewer, QWidget* parent)
    : ReviewPage(history, viewer, lesson::lessonsDirectory(), parent) {}

ReviewPage::ReviewPage(assessment::HistoryDatabase& history, const assessment::Viewer& viewer,
                       const QString& lessonsDirectory, QWidget* parent)
    : QWidget(parent), history_(history), viewer_(viewer),
      catalog_(std::make_unique<ReviewCatalog>(lessonsDirectory)) {
  // top bar: who is signed in, the group filter, exports, sign out
  who_ = new QLabel;
  groupCombo_ = new QComboBox;
  auto* csvButton = new QPushButton(tr("Export CSV…"));
  auto* refreshButton = new QPushButton(tr("Refresh"));
  auto* signOut = new QPushButton(tr("Sign out"));
  message_ = new QLabel;
  message_->setWordWrap(true);
  auto* bar = new QHBoxLayout;
  bar->addWidget(who_);
  bar->addStretch(1);
  bar->addWidget(new QLabel(tr("Group:")));
  bar->addWidget(groupCombo_);
  bar->addWidget(csvButton);
  bar->addWidget(refreshButton);
  bar->addWidget(signOut);
  connect(groupCombo_, &QComboBox::currentIndexChanged, this, [this] { buildGrid(); });
  connect(csvButton, &QPushButton::clicked, this, [this] { exportCsv(); });
  connect(refreshButton, &QPushButton::clicked, this, &ReviewPage::refresh);
  connect(signOut, &QPushButton::clicked, this, &ReviewPage::signOutRequested);

  // overview
  grid_ = new QTableWidget;
  grid_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  grid_->verticalHeader()->hide();
  grid_->setWordWrap(true);
  connect(grid_, &QTableWidget::cellActivated, this, [this](int row, int column) {
    if (row < 0 || row >= int(rows_.size())) return;
    const int lesson = column - kFixedColumns;
    showTrainee(rows_[std::size_t(row)].trainee.id,
                lesson >= 0 && lesson < lessons_.size() ? lessons_[lesson].id : QString());
  });
  auto* legend = new QLabel(tr("Best score (attempts). ✓ passed, ★ proficient: the pass mark on two "
                               "consecutive Test attempts. Double-click a cell for the history."));
  legend->setWordWrap(true);
  auto* overview = new QWidget;
  auto* overviewLayout = new QVBoxLayout(overview);
  overviewLayout->addWidget(grid_, 1);
  overviewLayout->addWidget(legend);

  // history
  traineeCombo_ = new QComboBox;
  lessonCombo_ = new QComboBox;
  auto* pdfButton = new QPushButton(tr("PDF report…"));
  historyView_ = new TraineeHistoryView;
  auto* choosers = new QHBoxLayout;
  choosers->addWidget(new QLabel(tr("Trainee:")));
  choosers->addWidget(traineeCombo_, 1);
  choosers->addWidget(new QLabel(tr("Lesson:")));
  choosers->addWidget(lessonCombo_, 1);
  choosers->addWidget(pdfButton);
  auto* historyTab = new QWidget;
  auto* historyLayout = new QVBoxLayout(historyTab);
  historyLayout->addLayout(choosers);
  historyLayout->addWidget(historyView_, 1);
  connect(traineeCombo_, &QComboBox::currentIndexChanged, this, [this] { showHistory(); });
  connect(lessonCombo_, &QComboBox::currentIndexChanged, this, [this] { showHistory(); });
  connect(pdfButton, &QPushButton::clicked, this, [this] { exportPdf(); });
  connect(historyView_, &TraineeHistoryView::attemptChosen, this, &ReviewPage::showAttempt);

  // attempt
  detailView_ = new AttemptDetailView;
  connect(detailView_, &AttemptDetailView::annotationRequested, this, &ReviewPage::annotate);

  tabs_ = new QTabWidget;
  tabs_->addTab(overview, tr("Overview"));
  tabs_->addTab(historyTab, tr("History"));
  tabs_->addTab(detailView_, tr("Attempt"));

  auto* layout = new QVBoxLayout(this);
  layout->addLayout(bar);
  layout->addWidget(message_);
  layout->addWidget(tabs_, 1);
  message_->hide();
  refresh();
}

ReviewPage::~ReviewPage() = default;

void ReviewPage::refresh() {
  // what this viewer may see: an instructor everyone, a trainee only themselves
  people_.clear();
  assessment::PeopleStore people(history_);
  if (viewer_.role == Role::Instructor) {
    for (const Trainee& t : people.trainees()) {
      if (t.role == Role::Trainee) people_ << t;
    }
  } else if (auto self = people.person(viewer_.userId)) {
    people_ << *self;
  }
  assessment::AttemptStore attempts(history_);
  attempts_ = attempts.list(viewer_);
  if (!attempts.lastError().ok()) say(tr("The history could not be read."), true);
  lessons_ = catalog_->lessons(attempts_);

  const QString me = [this, &people] {
    auto self = people.person(viewer_.userId);
    return self ? self->name : QString();
  }();
  who_->setText(viewer_.role == Role::Instructor ? tr("Instructor: %1").arg(me) : tr("Trainee: %1").arg(me));

  {
    const QSignalBlocker block(groupCombo_);
    const QString group = groupCombo_->currentData().toString();
    groupCombo_->clear();
    groupCombo_->addItem(tr("All groups"), QString());
    QStringList groups;
    for (const Trainee& t : people_) {
      if (!t.group.isEmpty() && !groups.contains(t.group)) groups << t.group;
    }
    groups.sort();
    for (const QString& g : groups) groupCombo_->addItem(g, g);
    groupCombo_->setCurrentIndex(std::max(0, groupCombo_->findData(group)));
    groupCombo_->setEnabled(viewer_.role == Role::Instructor);
  }
  {
    const QSignalBlocker block(traineeCombo_);
    const qint64 current = traineeCombo_->currentData().toLongLong();
    traineeCombo_->clear();
    for (const Trainee& t : people_) {
      traineeCombo_->addItem(t.group.isEmpty() ? t.name : tr("%1 (%2)").arg(t.name, t.group), t.id);
    }
    traineeCombo_->setCurrentIndex(std::max(0, traineeCombo_->findData(current)));
  }
  {
    const QSignalBlocker block(lessonCombo_);
    const QString current = lessonCombo_->currentData().toString();
    lessonCombo_->clear();
    for (const ReviewLesson& l : lessons_) lessonCombo_->addItem(l.title, l.id);
    lessonCombo_->setCurrentIndex(std::max(0, lessonCombo_->findData(current)));
  }
  buildGrid();
  showHistory();
}

void ReviewPage::setGroupFilter(const QString& group) {
  groupCombo_->setCurrentIndex(std::max(0, groupCombo_->findData(group)));
}

QList<Trainee> ReviewPage::shownTrainees() const {
  QList<Trainee> out;
  for (const GridRow& r : rows_) out << r.trainee;
  return out;
}

void ReviewPage::buildGrid() {
  rows_ = gui::buildGrid(people_, attempts_, *catalog_, groupCombo_->currentData().toString());
  grid_->clear();
  grid_->setRowCount(int(rows_.size()));
  grid_->setColumnCount(kFixedColumns + int(lessons_.size()));
  QStringList headers{tr("Trainee"), tr("Group")};
  for (const ReviewLesson& l : lessons_) headers << l.title;
  grid_->setHorizontalHeaderLabels(headers);
  const QLocale locale;
  for (int r = 0; r < int(rows_.size()); ++r) {
    const GridRow& row = rows_[std::size_t(r)];
    grid_->setItem(r, 0, new QTableWidgetItem(row.trainee.name));
    grid_->setItem(r, 1, new QTableWidgetItem(row.trainee.group));
    for (int c = 0; c < lessons_.size(); ++c) {
      auto* item = new QTableWidgetItem;
      item->setTextAlignment(Qt::AlignCenter);
      // the status word under the score: the same word the trainee's lesson list shows
      auto it = row.cells.constFind(lessons_[c].id);
      if (it != row.cells.cend()) {
        const GridCell& cell = it.value();
        QString text = cell.best ? locale.toString(*cell.best, 'f', 0) : QStringLiteral("–");
        text += QStringLiteral(" (%1)").arg(cell.attempts);
        if (cell.status == LessonStatus::Passed) text += QStringLiteral(" ✓");
        if (cell.status == LessonStatus::Proficient) text += QStringLiteral(" ✓★");
        item->setText(text + QLatin1Char('\n') + LessonStatusText::word(cell.status));
        item->setBackground(cellColour(cell));
        item->setToolTip(tr("%n attempt(s): %1 finished, %2 abandoned", nullptr, cell.attempts)
                             .arg(cell.finished)
                             .arg(cell.abandoned));
      } else {
        item->setText(LessonStatusText::word(LessonStatus::NotStarted));
        item->setForeground(QColor(120, 120, 120));
      }
      grid_->setItem(r, kFixedColumns + c, item);
    }
  }
  grid_->resizeColumnsToContents();
  grid_->resizeRowsToContents();
}

const Trainee* ReviewPage::shownTrainee() const {
  const qint64 id = traineeCombo_->currentData().toLongLong();
  for (const Trainee& t : people_) {
    if (t.id == id) return &t;
  }
  return nullptr;
}

QString ReviewPage::personName(qint64 id) const {
  for (const Trainee& t : people_) {
    if (t.id == id) return t.name;
  }
  return {};
}

void ReviewPage::showTrainee(qint64 traineeId, const QString& lesson) {
  QString chosen = lesson;
  if (chosen.isEmpty()) {
    for (const AttemptSummary& a : attempts_) {
      if (a.traineeId == traineeId) chosen = a.lesson;  // oldest first: ends on the latest
    }
  }
  {
    const QSignalBlocker a(traineeCombo_);
    const QSignalBlocker b(lessonCombo_);
    traineeCombo_->setCurrentIndex(std::max(0, traineeCombo_->findData(traineeId)));
    if (!chosen.isEmpty()) lessonCombo_->setCurrentIndex(std::max(0, lessonCombo_->findData(chosen)));
  }
  showHistory();
  tabs_->setCurrentIndex(1);
}

void ReviewPage::showHistory() {
  const Trainee* trainee = shownTrainee();
  const QString lesson = lessonCombo_->currentData().toString();
  if (!trainee) {
    historyView_->setHistory({}, {}, nullptr);
    return;
  }
  const QList<AttemptSummary> done = finishedAttempts(attempts_, trainee->id, lesson);
  QList<QList<assessment::StoredMetric>> metrics;
  for (const AttemptSummary& a : done) {
    auto detail = assessment::readAttemptDetail(history_, viewer_, a.id);
    metrics << (detail ? detail->metrics : QList<assessment::StoredMetric>{});
  }
  historyView_->setHistory(done, metrics, catalog_->rubric(lesson));
}

void ReviewPage::showAttempt(qint64 attemptId) {
  auto detail = assessment::readAttemptDetail(history_, viewer_, attemptId);
  if (!detail) {
    say(tr("That attempt could not be read."), true);
    return;
  }
  const ReviewLesson* lesson = catalog_->lesson(detail->summary.lesson);
  detailView_->setAttempt(*detail, personName(detail->summary.traineeId),
                          lesson ? lesson->title : detail->summary.lesson, lesson ? lesson->scenePath : QString(),
                          viewer_.role == Role::Instructor);
  tabs_->setCurrentIndex(2);
}

void ReviewPage::annotate(qint64 attemptId, const QString& note) {
  assessment::AnnotationStore notes(history_);
  if (!notes.add(viewer_, attemptId, note)) {
    say(notes.lastError().error == assessment::HistoryError::Forbidden
            ? tr("Only instructors can add notes.")
            : tr("The note could not be stored."),
        true);
    return;
  }
  say(tr("Note added."));
  showAttempt(attemptId);
}

bool ReviewPage::exportCsv() {
  QString path = csvPath_;
  if (path.isEmpty()) {
    path = QFileDialog::getSaveFileName(this, tr("Export attempts as CSV"), QStringLiteral("attempts.csv"),
                                        tr("CSV files (*.csv)"));
    if (path.isEmpty()) return false;
  }
  QString error;
  if (!ReviewReport::writeCsv(history_, viewer_, path, &error)) {
    say(error, true);
    return false;
  }
  say(tr("Exported the attempts to %1.").arg(path));
  return true;
}

bool ReviewPage::exportPdf() {
  const Trainee* trainee = shownTrainee();
  if (!trainee) {
    say(tr("Choose a trainee first."), true);
    return false;
  }
  QString path = pdfPath_;
  if (path.isEmpty()) {
    path = QFileDialog::getSaveFileName(this, tr("Save the report as PDF"), trainee->name + QStringLiteral(".pdf"),
                                        tr("PDF files (*.pdf)"));
    if (path.isEmpty()) return false;
  }
  TraineeReport report{*trainee, {}, {}};
  assessment::ScoreStore scores(history_);
  for (const AttemptSummary& a : attempts_) {
    if (a.traineeId != trainee->id) continue;
    report.attempts << a;
    // the opened vessel of an attempt whose end product has errors (its pierces read only then)
    if (!a.score) continue;
    const std::optional<assessment::StoredEndProduct> endProduct = scores.endProduct(viewer_, a.id);
    if (!endProduct || endProduct->errors.isEmpty()) continue;
    if (const auto detail = assessment::readAttemptDetail(history_, viewer_, a.id))
      report.endProducts.insert(a.id, openedVessel(*detail));
  }
  QString error;
  if (!ReviewReport::writePdf(report, *catalog_, path, &error)) {
    say(error, true);
    return false;
  }
  say(tr("Saved the report to %1.").arg(path));
  return true;
}

void ReviewPage::say(const QString& text, bool error) {
  message_->setText(text);
  message_->setStyleSheet(error ? QStringLiteral("color: #b00020;") : QString());
  message_->show();
}

QString ReviewPage::message() const { return message_->text(); }

}  // namespace microsim::gui
