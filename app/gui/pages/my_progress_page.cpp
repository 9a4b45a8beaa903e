#include "gui/pages/my_progress_page.h"

#include "gui/review/attempt_detail_view.h"
#include "gui/review/trainee_history_view.h"

#include "microsim/assessment/scoring/rubric.h"

#include <QChartView>
#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <optional>
#include <utility>
#include <variant>

namespace microsim::gui {

MyProgressPage::MyProgressPage(QString historyLocation, QWidget* parent)
    : QWidget(parent), loader_(std::make_unique<TraineeProgressLoader>(std::move(historyLocation))) {
  setObjectName(QStringLiteral("myProgressPage"));
  auto* heading = new QLabel(tr("<h2>My progress</h2>"), this);
  lessonCombo_ = new QComboBox(this);
  lessonCombo_->setObjectName(QStringLiteral("progressLessonChooser"));
  auto* backButton = new QPushButton(tr("Back to the lessons"), this);
  backButton->setObjectName(QStringLiteral("progressBackButton"));
  auto* bar = new QHBoxLayout;
  bar->addWidget(heading);
  bar->addStretch(1);
  bar->addWidget(new QLabel(tr("Lesson:"), this));
  bar->addWidget(lessonCombo_, 1);
  bar->addWidget(backButton);

  message_ = new QLabel(this);
  message_->setObjectName(QStringLiteral("progressMessage"));
  message_->setWordWrap(true);

  // the view scrolls its charts itself (trainee_history_view.cpp)
  historyView_ = new TraineeHistoryView;
  detailView_ = new AttemptDetailView;
  tabs_ = new QTabWidget(this);
  tabs_->addTab(historyView_, tr("Scores"));
  tabs_->addTab(detailView_, tr("Attempt"));

  auto* layout = new QVBoxLayout(this);
  layout->addLayout(bar);
  layout->addWidget(message_);
  layout->addWidget(tabs_, 1);

  // leaving stops a replay that may be running
  connect(backButton, &QPushButton::clicked, this, [this] {
    detailView_->clear();
    Q_EMIT back();
  });
  connect(lessonCombo_, &QComboBox::currentIndexChanged, this, &MyProgressPage::loadLesson);
  connect(loader_.get(), &TraineeProgressLoader::loaded, this, &MyProgressPage::showProgress);
  // a selected attempt is shown in the Attempt tab; an activated one (double-click, Return) opens it
  connect(historyView_->attemptsTable(), &QTableWidget::itemSelectionChanged, this, [this] {
    const QList<QTableWidgetItem*> selected = historyView_->attemptsTable()->selectedItems();
    if (!selected.isEmpty()) showAttempt(selected.first()->data(Qt::UserRole).toLongLong());
  });
  connect(historyView_, &TraineeHistoryView::attemptChosen, this, [this](qint64 attemptId) {
    showAttempt(attemptId);
    tabs_->setCurrentWidget(detailView_);
  });
}

MyProgressPage::~MyProgressPage() = default;

void MyProgressPage::open(const std::vector<lesson::Lesson>& lessons, const assessment::Viewer& viewer,
                          const QString& name, const QString& lessonId, const QString& language) {
  lessons_ = lessons;
  viewer_ = viewer;
  name_ = name;
  language_ = language;
  {
    const QSignalBlocker block(lessonCombo_);
    lessonCombo_->clear();
    for (const lesson::Lesson& l : lessons_) lessonCombo_->addItem(l.title.in(language_), l.id);
    lessonCombo_->setCurrentIndex(std::max(0, lessonCombo_->findData(lessonId)));
  }
  tabs_->setCurrentIndex(0);
  loadLesson();
}

QString MyProgressPage::lessonId() const { return lessonCombo_->currentData().toString(); }
QString MyProgressPage::message() const { return message_->text(); }

const lesson::Lesson* MyProgressPage::shownLesson() const {
  const QString id = lessonId();
  for (const lesson::Lesson& l : lessons_) {
    if (l.id == id) return &l;
  }
  return nullptr;
}

void MyProgressPage::loadLesson() {
  progress_ = {};
  historyView_->setHistory({}, {}, nullptr);
  detailView_->clear();
  message_->setText(tr("Reading your history…"));
  loader_->load(viewer_, lessonId());
}

void MyProgressPage::showProgress(const TraineeProgress& progress) {
  if (progress.lesson != lessonId()) return;
  progress_ = progress;
  if (!progress_.status.ok()) {
    message_->setText(tr("Your history could not be read (%1).").arg(progress_.status.driverMessage));
    Q_EMIT loaded();
    return;
  }

  QList<QList<assessment::StoredMetric>> metrics;
  int annotated = 0;
  for (const assessment::AttemptDetail& d : progress_.details) {
    metrics << d.metrics;
    if (!d.annotations.isEmpty()) ++annotated;
  }
  const lesson::Lesson* lesson = shownLesson();
  // the rubric gives the pass mark and the target bands (a file, not the history)
  std::optional<assessment::Rubric> rubric;
  if (lesson) {
    auto read = assessment::loadRubric(lesson->rubricPath.toStdString());
    if (auto* r = std::get_if<assessment::Rubric>(&read)) rubric = std::move(*r);
  }
  historyView_->setHistory(progress_.finished, metrics, rubric ? &*rubric : nullptr);

  message_->setText(annotated > 0 ? tr("%n of these attempts carry an instructor's note: choose one to read it.",
                                       nullptr, annotated)
                                  : QString());
  if (!progress_.finished.isEmpty()) showAttempt(progress_.finished.constLast().id);
  Q_EMIT loaded();
}

void MyProgressPage::showAttempt(qint64 attemptId) {
  for (const assessment::AttemptDetail& d : progress_.details) {
    if (d.summary.id != attemptId) continue;
    const lesson::Lesson* lesson = shownLesson();
    detailView_->setAttempt(d, name_, lesson ? lesson->title.in(language_) : d.summary.lesson,
                            lesson ? lesson->scenePath : QString(), false);
    return;
  }
}

}  // namespace microsim::gui
