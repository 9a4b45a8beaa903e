#include "gui/pages/lesson_list_page.h"

#include "microsim/assessment/scoring/rubric.h"
#include "microsim/assessment/storage/attempt_store.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace microsim::gui {

LessonListPage::LessonListPage(const QString& historyLocation, QWidget* parent)
    : QWidget(parent), reader_(historyLocation.isEmpty() ? nullptr : new HistoryReader(historyLocation, this)) {
  setObjectName(QStringLiteral("lessonListPage"));
  heading_ = new QLabel(this);
  table_ = new QTableWidget(0, 2, this);
  table_->setObjectName(QStringLiteral("lessonTable"));
  table_->setHorizontalHeaderLabels({tr("Lesson"), tr("Status")});
  table_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
  table_->horizontalHeader()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
  table_->verticalHeader()->hide();
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setSelectionMode(QAbstractItemView::SingleSelection);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  goals_ = new QLabel(this);
  goals_->setWordWrap(true);
  goals_->setObjectName(QStringLiteral("lessonGoals"));
  learn_ = new QPushButton(tr("Learn (guided)"), this);
  learn_->setObjectName(QStringLiteral("learnButton"));
  test_ = new QPushButton(tr("Test (graded)"), this);
  test_->setObjectName(QStringLiteral("testButton"));
  auto* signOut = new QPushButton(tr("Sign out"), this);
  signOut->setObjectName(QStringLiteral("signOutButton"));
  progress_ = new QPushButton(tr("My progress"), this);
  progress_->setObjectName(QStringLiteral("myProgressButton"));
  progress_->setToolTip(tr("Your scores over your attempts, each attempt's feedback and your instructors' notes"));

  auto* buttons = new QHBoxLayout;
  buttons->addWidget(signOut);
  buttons->addWidget(progress_);
  buttons->addStretch(1);
  buttons->addWidget(learn_);
  buttons->addWidget(test_);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(heading_);
  layout->addWidget(table_, 1);
  layout->addWidget(goals_);
  layout->addLayout(buttons);

  connect(table_, &QTableWidget::itemSelectionChanged, this, &LessonListPage::showGoals);
  connect(table_, &QTableWidget::cellDoubleClicked, this, [this] { start(assessment::AttemptMode::Learn); });
  connect(learn_, &QPushButton::clicked, this, [this] { start(assessment::AttemptMode::Learn); });
  connect(test_, &QPushButton::clicked, this, [this] { start(assessment::AttemptMode::Test); });
  connect(signOut, &QPushButton::clicked, this, &LessonListPage::signOut);
  connect(progress_, &QPushButton::clicked, this, [this] {
    const int row = selectedRow();
    Q_EMIT showProgress(row >= 0 ? lessons_[static_cast<std::size_t>(row)].id : QString());
  });
}

void LessonListPage::show(const std::vector<lesson::Lesson>& lessons, const assessment::Viewer& viewer,
                          const QString& name, const QString& language) {
  const int previous = selectedRow();
  lessons_ = lessons;
  language_ = language;
  heading_->setText(tr("<h2>Lessons for %1</h2>").arg(name.toHtmlEscaped()));
  const bool stored = reader_ && viewer.userId != 0;
  // a guest's attempts are not stored: there is no progress to show
  progress_->setEnabled(stored);

  table_->setRowCount(static_cast<int>(lessons_.size()));
  statuses_.assign(lessons_.size(), LessonStatus::NotStarted);
  for (std::size_t i = 0; i < lessons_.size(); ++i) {
    const int row = static_cast<int>(i);
    table_->setItem(row, 0, new QTableWidgetItem(lessons_[i].title.in(language_)));
    table_->setItem(row, 1, new QTableWidgetItem(QStringLiteral("…")));
  }
  selectRow(previous >= 0 && previous < table_->rowCount() ? previous : 0);
  statusesLoaded_ = false;
  if (!stored) {
    showStatuses({}, viewer.userId, {});
    return;
  }
  using Attempts = QList<assessment::AttemptSummary>;
  struct Read {
    Attempts attempts;
    QString error;
  };
  reader_->read<Read>(
      [viewer](assessment::HistoryDatabase& history) {
        assessment::AttemptStore store(history);
        Read read{store.list(viewer, viewer.userId), {}};
        if (!store.lastError().ok()) read.error = store.lastError().driverMessage;
        return read;
      },
      [](const QString& why) { return Read{{}, why}; },
      [this, user = viewer.userId](const Read& read) { showStatuses(read.attempts, user, read.error); });
}

void LessonListPage::showStatuses(const QList<assessment::AttemptSummary>& attempts, qint64 userId,
                                  const QString& error) {
  statuses_.clear();
  for (std::size_t i = 0; i < lessons_.size(); ++i) {
    const lesson::Lesson& l = lessons_[i];
    const auto rubric = assessment::loadRubric(l.rubricPath.toStdString());
    const assessment::Rubric* r = std::get_if<assessment::Rubric>(&rubric);
    const LessonStatus status = lessonStatus(attempts, userId, l.id, r);
    statuses_.push_back(status);
    auto* statusItem = new QTableWidgetItem(error.isEmpty() ? LessonStatusText::word(status) : QStringLiteral("—"));
    if (!error.isEmpty()) statusItem->setToolTip(tr("The history could not be read: %1").arg(error));
    if (error.isEmpty() && (status == LessonStatus::Passed || status == LessonStatus::Proficient))
      statusItem->setForeground(QColor(0x1b, 0x7f, 0x3a));
    table_->setItem(static_cast<int>(i), 1, statusItem);
  }
  statusesLoaded_ = true;
  Q_EMIT statusesShown();
}

QString LessonListPage::statusText(int row) const { return table_->item(row, 1)->text(); }

int LessonListPage::selectedRow() const {
  const QList<QTableWidgetItem*> selected = table_->selectedItems();
  return selected.isEmpty() ? -1 : selected.first()->row();
}

void LessonListPage::selectRow(int row) {
  if (row >= 0 && row < table_->rowCount()) table_->selectRow(row);
  showGoals();
}

void LessonListPage::showGoals() {
  const int row = selectedRow();
  learn_->setEnabled(row >= 0);
  test_->setEnabled(row >= 0);
  if (row < 0) {
    goals_->clear();
    return;
  }
  QString text = tr("<b>Goals</b><ul>");
  for (const lesson::Text& g : lessons_[static_cast<std::size_t>(row)].goals)
    text += QStringLiteral("<li>%1</li>").arg(g.in(language_).toHtmlEscaped());
  goals_->setText(text + QStringLiteral("</ul>"));
}

void LessonListPage::start(assessment::AttemptMode mode) {
  const int row = selectedRow();
  if (row >= 0) Q_EMIT startLesson(row, mode);
}

}  // namespace microsim::gui
