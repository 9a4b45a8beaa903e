#include "gui/pages/attempt_page.h"

#include "gui/number_format.h"
#include "gui/session/attempt_session.h"
#include "gui/settings/scene_overrides.h"
#include "gui/settings/tunables.h"
#include "gui/simulation_runner.h"
#include "gui/viewport.h"
#include "tracking/manual_source.h"

#include <QCoreApplication>
#include <QDir>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QListWidget>
#include <QMessageBox>
#include <QPushButton>
#include <QStandardPaths>
#include <QVBoxLayout>

#include <algorithm>

namespace microsim::gui {

namespace {

std::vector<Guide> viewportGuides(const lesson::Lesson& lesson, const std::vector<bool>& hit) {
  std::vector<Guide> guides;
  for (std::size_t i = 0; i < lesson.guides.size(); ++i) {
    const lesson::Guide& g = lesson.guides[i];
    const bool done = i < hit.size() && hit[i];
    guides.push_back({Guide::Kind::Target, g.target, g.direction, 0.12, done});
    // the arrow ends at the target: the needle arrives along the ideal direction
    guides.push_back({Guide::Kind::NeedleDirection, g.target - 0.5 * g.direction, g.direction, 0.5, done});
  }
  return guides;
}

}  // namespace

AttemptPage::AttemptPage(assessment::HistoryDatabase* history, QWidget* parent)
    : QWidget(parent), history_(history) {
  setObjectName(QStringLiteral("attemptPage"));
  viewport_ = new Viewport(this);
  viewport_->setObjectName(QStringLiteral("attemptViewport"));
  viewport_->installEventFilter(this);
  manual_ = new tracking::ManualSource(this);

  title_ = new QLabel(this);
  title_->setWordWrap(true);
  mode_ = new QLabel(this);
  mode_->setObjectName(QStringLiteral("attemptMode"));
  mode_->setWordWrap(true);  // the Learn-mode line is longer than the side panel is wide
  steps_ = new QListWidget(this);
  steps_->setObjectName(QStringLiteral("stepList"));
  steps_->setWordWrap(true);
  steps_->setFocusPolicy(Qt::NoFocus);
  status_ = new QLabel(this);
  status_->setWordWrap(true);
  status_->setObjectName(QStringLiteral("attemptStatus"));
  cut_ = new QLabel(this);
  cut_->setWordWrap(true);
  cut_->setObjectName(QStringLiteral("attemptCut"));
  cut_->hide();
  tooShort_ = new QLabel(this);
  tooShort_->setWordWrap(true);
  tooShort_->setObjectName(QStringLiteral("attemptThreadTooShort"));
  tooShort_->setStyleSheet(QStringLiteral("color: #b35900; font-weight: bold;"));
  tooShort_->hide();
  finish_ = new QPushButton(tr("Finish attempt"), this);
  finish_->setObjectName(QStringLiteral("finishButton"));
  abandon_ = new QPushButton(tr("Abandon"), this);
  abandon_->setObjectName(QStringLiteral("abandonButton"));
  for (QPushButton* b : {finish_, abandon_}) b->setFocusPolicy(Qt::NoFocus);

  auto* side = new QVBoxLayout;
  side->addWidget(title_);
  side->addWidget(mode_);
  side->addWidget(steps_, 1);
  side->addWidget(status_);
  side->addWidget(cut_);
  side->addWidget(tooShort_);
  side->addWidget(finish_);
  side->addWidget(abandon_);
  auto* panel = new QWidget(this);
  panel->setLayout(side);
  panel->setFixedWidth(300);
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(viewport_, 1);
  layout->addWidget(panel);

  connect(finish_, &QPushButton::clicked, this, &AttemptPage::finish);
  connect(abandon_, &QPushButton::clicked, this, &AttemptPage::confirmAbandon);
}

AttemptPage::~AttemptPage() { closeSession(); }

void AttemptPage::closeSession() {
  if (!session_) return;
  manual_->stop();
  viewport_->setManualSource(nullptr);
  viewport_->setRunner(nullptr);
  session_.reset();  // an attempt left in progress becomes interrupted at the next open
}

bool AttemptPage::begin(const lesson::Lesson& lesson, int lessonIndex, assessment::AttemptMode mode,
                        const assessment::Viewer& viewer, const QString& language, QString* error) {
  closeSession();
  lesson_ = lesson;
  language_ = language;
  replaying_ = false;

  AttemptSetup setup;
  setup.lesson = lesson;
  setup.lessonIndex = lessonIndex;
  setup.mode = mode;
  setup.viewer = viewer;
  setup.historyLocation = history_ && history_->isOpen() ? history_->location() : QString();
  setup.solver = settings::solverOverrideFromSettings();
  setup.recordingFolder =
      QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)).filePath(QStringLiteral("recordings"));
  auto session = std::make_unique<AttemptSession>();
  AttemptProblem problem;
  if (!session->prepare(setup, &problem)) {
    *error = describe(problem);
    return false;
  }
  session_ = std::move(session);
  connect(session_.get(), &AttemptSession::progressed, this, &AttemptPage::showProgress);
  connect(session_.get(), &AttemptSession::begun, this, [this](qint64 id) {
    // a refusal the history gave (failed, just before) says more than this
    if (id == 0 && status_->text().isEmpty()) status_->setText(tr("This attempt is not stored (no history)."));
  });
  connect(session_.get(), &AttemptSession::failed, this,
          [this](const AttemptProblem& p) { status_->setText(describe(p)); });
  connect(session_.get(), &AttemptSession::replayEnded, this, [this] { replaying_ = false; });
  connect(session_.get(), &AttemptSession::finished, this, [this](const AttemptResult& result) {
    status_->clear();
    Q_EMIT finished(result);
  });
  connect(session_.get(), &AttemptSession::abandoned, this, [this] { Q_EMIT abandoned(); });
  connect(manual_, &tracking::TrackerSource::frameReady, session_->runner(), &SimulationRunner::submitFrame);

  title_->setText(QStringLiteral("<h3>%1</h3>").arg(lesson.title.in(language).toHtmlEscaped()));
  // Learn mode draws the lesson's marks; a lesson without any (the instrument tie) still
  // ticks its steps off as they are done
  if (mode != assessment::AttemptMode::Learn)
    mode_->setText(tr("Test mode: graded, no hints."));
  else if (lesson.guides.empty())
    mode_->setText(tr("Learn mode: each step is ticked off as you do it."));
  else
    mode_->setText(tr("Learn mode: follow the marks."));
  steps_->clear();
  for (const lesson::Step& s : lesson.steps) steps_->addItem(s.instruction.in(language));
  status_->setText(setup.historyLocation.isEmpty() || viewer.userId == 0
                       ? tr("This attempt is not stored (no history).")
                       : QString());
  finish_->setEnabled(true);
  abandon_->setEnabled(true);
  viewport_->setRunner(session_->runner());
  viewport_->sceneChanged();
  viewport_->setGuides(mode == assessment::AttemptMode::Learn ? viewportGuides(lesson, {}) : std::vector<Guide>{});
  applyViewSettings();
  showProgress(session_->progress());
  return true;
}

void AttemptPage::applyViewSettings() {
  const QStringList modes = {QStringLiteral("mono"), QStringLiteral("quad"), QStringLiteral("anaglyph"),
                             QStringLiteral("side")};
  const int mode = static_cast<int>(modes.indexOf(settings::Tunables::value(settings::stereoKey()).toString()));
  viewport_->setStereoMode(static_cast<StereoMode>(std::max(0, mode)));
}

void AttemptPage::startLive() {
  if (!isActive()) return;
  replaying_ = false;
  manual_->placeTools(session_->sceneDef());
  viewport_->setManualSource(manual_);
  manual_->start();
  session_->startLive();
  viewport_->setFocus();
}

void AttemptPage::replay(std::vector<sim::InputFrame> frames, bool finishAtEnd) {
  if (!isActive()) return;
  manual_->stop();
  viewport_->setManualSource(nullptr);
  replaying_ = true;
  status_->setText(tr("Replaying a recording…"));
  session_->replay(std::move(frames), finishAtEnd);
  viewport_->sceneChanged();
}

void AttemptPage::finish() {
  if (!isActive()) return;
  manual_->stop();
  finish_->setEnabled(false);
  abandon_->setEnabled(false);
  status_->setText(tr("Scoring…"));
  session_->finish();
}

void AttemptPage::confirmAbandon() {
  if (!isActive()) return;
  QMessageBox box(QMessageBox::Question, tr("Abandon the attempt?"),
                  tr("The attempt ends here without a score. It stays in your history as abandoned."),
                  QMessageBox::Yes | QMessageBox::No, this);
  box.setObjectName(QStringLiteral("abandonConfirmation"));
  box.button(QMessageBox::Yes)->setText(tr("Abandon"));
  box.button(QMessageBox::No)->setText(tr("Keep practising"));
  box.setDefaultButton(QMessageBox::No);
  if (box.exec() != QMessageBox::Yes || !isActive()) return;
  manual_->stop();
  finish_->setEnabled(false);
  abandon_->setEnabled(false);
  session_->abandon();
}

void AttemptPage::stop() {
  if (!session_) return;
  manual_->stop();
  session_->stop();
}

bool AttemptPage::isActive() const { return session_ && session_->isActive(); }
qint64 AttemptPage::attemptId() const { return session_ ? session_->attemptId() : 0; }
int AttemptPage::stepsDone() const { return session_ ? session_->progress().stepsDone : 0; }
SimulationRunner* AttemptPage::runner() const { return session_ ? session_->runner() : nullptr; }

void AttemptPage::showProgress(const AttemptProgress& progress) {
  const int done = progress.stepsDone;
  for (int i = 0; i < steps_->count(); ++i) {
    QListWidgetItem* item = steps_->item(i);
    const QString text = lesson_.steps[static_cast<std::size_t>(i)].instruction.in(language_);
    item->setText((i < done ? QStringLiteral("✔ ") : i == done ? QStringLiteral("➜ ") : QStringLiteral("   ")) + text);
    item->setForeground(i < done ? QColor(0x1b, 0x7f, 0x3a) : palette().color(QPalette::Text));
  }
  if (session_ && session_->setup().mode == assessment::AttemptMode::Learn)
    viewport_->setGuides(viewportGuides(lesson_, progress.guidesHit));
  // jaws that closed on nothing say so until a grasp holds something
  if (progress.emptyGraspHand >= 0) {
    status_->setText(progress.emptyGraspHand == static_cast<int>(sim::Hand::Left)
                         ? tr("The left forceps closed on nothing: nothing lay between its jaws.")
                         : tr("The right forceps closed on nothing: nothing lay between its jaws."));
    graspNoted_ = true;
  } else if (graspNoted_) {
    status_->clear();
    graspNoted_ = false;
  }
  showCuts(progress);
  if (done == static_cast<int>(lesson_.steps.size()) && !replaying_ && isActive())
    status_->setText(tr("Every step is done: finish the attempt when you are ready."));
}

void AttemptPage::showCuts(const AttemptProgress& progress) {
  const QString units = settings::Tunables::value(settings::unitsKey()).toString();
  cut_->setVisible(progress.threadCuts > 0);
  if (progress.threadCuts > 0)
    cut_->setText(progress.lastCutEndMm >= 0.0
                      ? tr("The scissors cut the thread: the cut end is %1 long.")
                            .arg(NumberFormat::value(progress.lastCutEndMm, "mm", units))
                      : tr("The scissors cut the thread: no stitch holds it on either side of the cut."));
  tooShort_->setVisible(progress.threadTooShortMm >= 0.0);
  if (progress.threadTooShortMm >= 0.0)
    tooShort_->setText(tr("Too short to tie: the needle keeps only %1 of thread.")
                           .arg(NumberFormat::value(progress.threadTooShortMm, "mm", units)));
}

QString AttemptPage::describe(const AttemptProblem& problem) {
  switch (problem.failure) {
    case AttemptFailure::RubricUnreadable:
      return tr("The rubric %1 cannot be read (field %2, line %3).").arg(problem.file, problem.field).arg(problem.line);
    case AttemptFailure::SceneUnreadable:
      return tr("The scene %1 cannot be loaded (field %2, line %3).").arg(problem.file, problem.field).arg(problem.line);
    case AttemptFailure::UnknownSolver:
      return tr("The tissue solver %1 chosen in the settings is not known; choose another.").arg(problem.field);
    case AttemptFailure::HistoryUnavailable:
      return tr("This attempt is not stored: the history refused it (%1).").arg(problem.driverMessage);
    case AttemptFailure::RecordingUnreadable:
      return tr("The recording %1 could not be replayed for scoring.").arg(problem.file);
    case AttemptFailure::ScoreNotStored:
      return tr("The score could not be stored (%1).").arg(problem.driverMessage);
    case AttemptFailure::AbandonNotStored:
      return tr("The history could not mark the attempt abandoned (%1).").arg(problem.driverMessage);
  }
  return {};
}

int AttemptPage::mapKey(int key, const QString& keyMap) {
  if (keyMap != QLatin1String("azerty")) return key;
  // AZERTY letters in the places of QWERTY's W, A and Q
  switch (key) {
    case Qt::Key_Z: return Qt::Key_W;
    case Qt::Key_Q: return Qt::Key_A;
    case Qt::Key_A: return Qt::Key_Q;
    case Qt::Key_W: return Qt::Key_Z;
    default: return key;
  }
}

bool AttemptPage::eventFilter(QObject* watched, QEvent* event) {
  static bool remapping = false;
  if (watched == viewport_ && !remapping &&
      (event->type() == QEvent::KeyPress || event->type() == QEvent::KeyRelease)) {
    auto* key = static_cast<QKeyEvent*>(event);
    const int mapped = mapKey(key->key(), settings::Tunables::value(settings::keyMapKey()).toString());
    if (mapped != key->key()) {
      QKeyEvent copy(key->type(), mapped, key->modifiers(), key->text(), key->isAutoRepeat(), key->count());
      remapping = true;
      QCoreApplication::sendEvent(viewport_, &copy);
      remapping = false;
      return true;
    }
  }
  return QWidget::eventFilter(watched, event);
}

}  // namespace microsim::gui
