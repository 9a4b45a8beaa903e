#include "gui/review/attempt_detail_view.h"

#include "gui/metric_vocabulary.h"
#include "gui/number_format.h"
#include "gui/pages/end_product_panel.h"
#include "gui/review/replay_controls.h"
#include "gui/review/replay_player.h"
#include "gui/review/review_data.h"
#include "gui/review/review_text.h"
#include "gui/viewport.h"
#include "microsim/assessment/scoring/pierce_fields.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QLocale>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSplitter>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>

namespace microsim::gui {
namespace {

QTableWidget* makeTable(const QStringList& headers) {
  auto* table = new QTableWidget(0, int(headers.size()));
  table->setHorizontalHeaderLabels(headers);
  table->horizontalHeader()->setStretchLastSection(true);
  table->verticalHeader()->hide();
  // rows as tall as their wrapped text at whatever width the splitter leaves
  table->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table->setSelectionBehavior(QAbstractItemView::SelectRows);
  return table;
}

void set(QTableWidget* table, int row, int column, const QString& text) {
  table->setItem(row, column, new QTableWidgetItem(text));
}


}  // namespace

AttemptDetailView::AttemptDetailView(QWidget* parent) : QWidget(parent) {
  heading_ = new QLabel;
  heading_->setTextFormat(Qt::PlainText);
  heading_->setWordWrap(true);
  neverEvents_ = new QLabel;
  neverEvents_->setWordWrap(true);
  neverEvents_->setStyleSheet(QStringLiteral("color: #b00020;"));

  metrics_ = makeTable({tr("Metric"), tr("Value"), tr("Target"), tr("Tolerance"), tr("Weight"), tr("Points"),
                        tr("Feedback")});
  QStringList pierceHeaders{tr("Pierce")};
  for (const assessment::PierceField& field : assessment::pierceFields())
    pierceHeaders << MetricVocabulary::pierceFieldTitle(field.key);
  pierces_ = makeTable(pierceHeaders);
  endProduct_ = new EndProductPanel(Qt::Vertical);

  annotations_ = new QListWidget;
  annotations_->setWordWrap(true);
  note_ = new QPlainTextEdit;
  note_->setPlaceholderText(tr("A note for this attempt…"));
  note_->setMaximumHeight(90);
  addNote_ = new QPushButton(tr("Add note"));
  connect(addNote_, &QPushButton::clicked, this, [this] {
    const QString text = note_->toPlainText().trimmed();
    if (text.isEmpty() || attemptId_ == 0) return;
    Q_EMIT annotationRequested(attemptId_, text);
  });
  auto* notes = new QWidget;
  auto* notesLayout = new QVBoxLayout(notes);
  notesLayout->addWidget(annotations_, 1);
  notesLayout->addWidget(note_);
  notesLayout->addWidget(addNote_, 0, Qt::AlignRight);

  auto* tabs = new QTabWidget;
  tabs->addTab(metrics_, tr("Metrics"));
  tabs->addTab(pierces_, tr("Pierces"));
  tabs->addTab(endProduct_, tr("End product"));
  tabs->addTab(notes, tr("Annotations"));

  auto* left = new QWidget;
  auto* leftLayout = new QVBoxLayout(left);
  leftLayout->setContentsMargins(0, 0, 0, 0);
  leftLayout->addWidget(heading_);
  leftLayout->addWidget(neverEvents_);
  leftLayout->addWidget(tabs, 1);

  // the replay: the viewport and the player's controls are made on first use (the viewport
  // needs an OpenGL context)
  replayArea_ = new QWidget;
  auto* replayLayout = new QVBoxLayout(replayArea_);
  replayLayout->setContentsMargins(0, 0, 0, 0);
  replay_ = new QPushButton(tr("Replay in 3D"));
  replayStatus_ = new QLabel;
  replayStatus_->setWordWrap(true);
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(replay_);
  buttons->addWidget(replayStatus_, 1);
  replayLayout->addLayout(buttons);
  replayLayout->addStretch(1);
  connect(replay_, &QPushButton::clicked, this, &AttemptDetailView::startReplay);

  auto* splitter = new QSplitter(Qt::Horizontal);
  splitter->addWidget(left);
  splitter->addWidget(replayArea_);
  splitter->setStretchFactor(0, 1);
  splitter->setStretchFactor(1, 1);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(splitter);
  clear();
}

AttemptDetailView::~AttemptDetailView() {
  // the viewport must not outlive the runner it draws
  if (viewport_) viewport_->setRunner(nullptr);
  delete player_;
  player_ = nullptr;
}

void AttemptDetailView::clear() {
  if (player_) player_->stop();
  attemptId_ = 0;
  recording_.clear();
  scenePath_.clear();
  heading_->setText(tr("Choose an attempt in a trainee's history."));
  neverEvents_->hide();
  metrics_->setRowCount(0);
  pierces_->setRowCount(0);
  endProduct_->clear();
  annotations_->clear();
  note_->clear();
  addNote_->setEnabled(false);
  note_->setEnabled(false);
  replay_->setEnabled(false);
  if (controls_) controls_->recordingUnloaded();
  replayStatus_->clear();
}

void AttemptDetailView::setAttempt(const assessment::AttemptDetail& detail, const QString& traineeName,
                                   const QString& lessonTitle, const QString& scenePath, bool canAnnotate) {
  clear();
  const assessment::AttemptSummary& a = detail.summary;
  attemptId_ = a.id;
  recording_ = detail.recording;
  scenePath_ = scenePath;
  const QLocale locale;
  QString text = tr("%1 — %2, %3, %4").arg(traineeName, lessonTitle, ReviewText::mode(a.mode),
                                           locale.toString(a.started.toLocalTime(), QLocale::ShortFormat));
  if (a.score) {
    text += QLatin1Char('\n') + tr("Score %1 of 100 (%2); rubric %3 version %4")
                                    .arg(locale.toString(*a.score, 'f', 1), a.passed ? tr("passed") : tr("not passed"),
                                         a.rubricId)
                                    .arg(a.rubricVersion);
  } else {
    text += QLatin1Char('\n') + ReviewText::status(a.status);
  }
  heading_->setText(text);
  fillMetrics(detail);
  fillPierces(detail);
  if (a.score) endProduct_->setEndProduct(openedVessel(detail), detail.endProduct.judged);
  fillAnnotations(detail);
  addNote_->setEnabled(canAnnotate);
  note_->setEnabled(canAnnotate);
  note_->setVisible(canAnnotate);
  addNote_->setVisible(canAnnotate);
  const bool replayable = !recording_.isEmpty() && !scenePath_.isEmpty();
  replay_->setEnabled(replayable);
  if (!replayable) replayStatus_->setText(recording_.isEmpty() ? tr("No recording stored.") : tr("The lesson's scene is not installed."));
}

void AttemptDetailView::fillMetrics(const assessment::AttemptDetail& detail) {
  const QLocale locale;
  metrics_->setRowCount(int(detail.metrics.size()));
  for (int row = 0; row < detail.metrics.size(); ++row) {
    const assessment::StoredMetric& m = detail.metrics[row];
    set(metrics_, row, 0, MetricVocabulary::metricLabel(m.key));
    const std::string unit = m.unit.toStdString();
    set(metrics_, row, 1, NumberFormat::value(m.value, unit));
    set(metrics_, row, 2, NumberFormat::value(m.target, unit));
    set(metrics_, row, 3, QStringLiteral("± ") + NumberFormat::value(m.tolerance, unit));
    set(metrics_, row, 4, locale.toString(m.weight, 'g', 3));
    set(metrics_, row, 5, NumberFormat::percent(m.points));
    set(metrics_, row, 6, ReviewText::feedback(m.feedback));
  }
  metrics_->resizeColumnsToContents();

  QStringList never;
  for (const QString& key : detail.neverEvents) never << ReviewText::feedback(key);
  neverEvents_->setText(never.join(QLatin1Char('\n')));
  neverEvents_->setVisible(!never.isEmpty());
}

void AttemptDetailView::fillPierces(const assessment::AttemptDetail& detail) {
  const std::vector<PierceRow> rows = pierceRows(detail.pierces);
  pierces_->setRowCount(int(rows.size()));
  for (int r = 0; r < int(rows.size()); ++r) {
    set(pierces_, r, 0, QString::number(rows[r].pierce + 1));
    int column = 1;
    for (const assessment::PierceField& field : assessment::pierceFields()) {
      const double v = rows[r].values.value(QString::fromUtf8(field.key.data(), qsizetype(field.key.size())), std::nan(""));
      QString text;
      if (field.unit == "flag")
        text = std::isnan(v) ? QStringLiteral("–") : (v > 0.5 ? tr("yes") : tr("no"));
      else
        // wall thicknesses are fractions near 2: one decimal would hide the difference
        text = NumberFormat::number(v, field.unit == "1" ? 2 : 1);
      set(pierces_, r, column++, text);
    }
  }
  pierces_->resizeColumnsToContents();
}

void AttemptDetailView::fillAnnotations(const assessment::AttemptDetail& detail) {
  const QLocale locale;
  for (const assessment::Annotation& n : detail.annotations) {
    annotations_->addItem(tr("%1, %2:\n%3")
                              .arg(n.authorName, locale.toString(n.created.toLocalTime(), QLocale::ShortFormat), n.note));
  }
}

bool AttemptDetailView::startReplay() {
  if (recording_.isEmpty() || scenePath_.isEmpty()) return false;
  if (!player_) {
    player_ = new ReplayPlayer;
    viewport_ = new Viewport;
    viewport_->setMinimumSize(320, 240);
    controls_ = new ReplayControls(player_);
    controls_->addShortcuts(replayArea_);
    auto* layout = static_cast<QVBoxLayout*>(replayArea_->layout());
    delete layout->takeAt(1);  // the stretch that kept the button at the top
    layout->insertWidget(1, viewport_, 1);
    layout->insertWidget(2, controls_);
    connect(player_, &ReplayPlayer::finished, this, [this] {
      replayStatus_->setText(tr("Replay finished: %n frame(s).", nullptr, player_->frameCount()));
    });
    connect(player_, &ReplayPlayer::playingChanged, this, [this](bool playing) {
      if (playing) replayStatus_->setText(tr("Replaying %n frame(s)…", nullptr, player_->frameCount()));
      else if (player_->target() < player_->frameCount()) replayStatus_->setText(tr("Paused."));
    });
  }
  viewport_->setRunner(nullptr);
  controls_->recordingUnloaded();
  const ReplayLoad loaded = player_->load(scenePath_, recording_);
  switch (loaded) {
    case ReplayLoad::Ok: break;
    case ReplayLoad::NoRecording: replayStatus_->setText(tr("No recording stored.")); return false;
    case ReplayLoad::BadRecording: replayStatus_->setText(tr("The stored recording is damaged.")); return false;
    case ReplayLoad::BadScene: replayStatus_->setText(tr("The lesson's scene could not be loaded.")); return false;
  }
  viewport_->setRunner(player_->runner());
  controls_->recordingLoaded();
  player_->play();
  return true;
}

}  // namespace microsim::gui
