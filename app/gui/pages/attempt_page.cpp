#include "gui/pages/attempt_page.h"

#include "gui/settings/scene_overrides.h"
#include "gui/settings/tunables.h"
#include "gui/simulation_runner.h"
#include "gui/viewport.h"
#include "lesson/progress.h"
#include "tracking/manual_source.h"

#include "microsim/assessment/scoring/attempt.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QStandardPaths>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace microsim::gui {

namespace {

QString dataFolder(const QString& name) {
  return QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)).filePath(name);
}

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
    : QWidget(parent), history_(history), runner_(std::make_unique<SimulationRunner>()) {
  qRegisterMetaType<microsim::gui::AttemptResult>();
  setObjectName(QStringLiteral("attemptPage"));
  viewport_ = new Viewport(this);
  viewport_->setObjectName(QStringLiteral("attemptViewport"));
  viewport_->installEventFilter(this);
  manual_ = new tracking::ManualSource(this);
  connect(manual_, &tracking::TrackerSource::frameReady, runner_.get(), &SimulationRunner::submitFrame);

  title_ = new QLabel(this);
  title_->setWordWrap(true);
  mode_ = new QLabel(this);
  mode_->setObjectName(QStringLiteral("attemptMode"));
  steps_ = new QListWidget(this);
  steps_->setObjectName(QStringLiteral("stepList"));
  steps_->setWordWrap(true);
  steps_->setFocusPolicy(Qt::NoFocus);
  status_ = new QLabel(this);
  status_->setWordWrap(true);
  status_->setObjectName(QStringLiteral("attemptStatus"));
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
  side->addWidget(finish_);
  side->addWidget(abandon_);
  auto* panel = new QWidget(this);
  panel->setLayout(side);
  panel->setFixedWidth(300);
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(viewport_, 1);
  layout->addWidget(panel);

  progressTimer_ = new QTimer(this);
  progressTimer_->setInterval(100);
  connect(progressTimer_, &QTimer::timeout, this, &AttemptPage::updateProgress);
  connect(runner_.get(), &SimulationRunner::replayFinished, this, [this] {
    if (!replaying_) return;
    if (finishAtEnd_) {
      finish();
      return;
    }
    progressTimer_->stop();
    updateProgress();
  });
  connect(finish_, &QPushButton::clicked, this, &AttemptPage::finish);
  connect(abandon_, &QPushButton::clicked, this, [this] {
    abandon();
    Q_EMIT abandoned();
  });
}

AttemptPage::~AttemptPage() {
  stopRunning();
  if (scoring_.joinable()) scoring_.join();
  viewport_->setRunner(nullptr);
}

bool AttemptPage::begin(const lesson::Lesson& lesson, int lessonIndex, assessment::AttemptMode mode,
                        const assessment::Viewer& viewer, const QString& language, QString* error) {
  abandon();
  lesson_ = lesson;
  lessonIndex_ = lessonIndex;
  attemptMode_ = mode;
  language_ = language;

  // rubric and scene (with the solver settings)
  const auto rubric = assessment::loadRubric(lesson.rubricPath.toStdString());
  if (const auto* e = std::get_if<assessment::RubricError>(&rubric)) {
    *error = tr("The rubric %1 cannot be read (field %2, line %3).")
                 .arg(QString::fromStdString(e->file), QString::fromStdString(e->field))
                 .arg(e->line);
    return false;
  }
  rubric_ = std::get<assessment::Rubric>(rubric);
  QString overrideError;
  scenePath_ = settings::applySolverOverride(lesson.scenePath, settings::solverOverrideFromSettings(),
                                             dataFolder(QStringLiteral("scenes")), &overrideError);
  if (scenePath_.isEmpty()) {
    *error = tr("The scene %1 cannot be prepared: %2").arg(lesson.scenePath, overrideError);
    return false;
  }
  // stepped deterministically, live too: the frames the attempt consumed replay to the very
  // states the trainee saw, and the score is computed on those (a slow step makes the scene
  // lag the hand rather than show a tissue the score will not see)
  sim::SceneError sceneError;
  if (!runner_->load(scenePath_, sim::StepMode::Deterministic, &sceneError)) {
    *error = tr("The scene %1 cannot be loaded (field %2, line %3).")
                 .arg(scenePath_, QString::fromStdString(sceneError.field))
                 .arg(sceneError.line);
    return false;
  }

  // the attempt in the history, and its recording file
  attemptId_ = 0;
  if (history_ && history_->isOpen() && viewer.userId != 0) {
    const std::optional<qint64> id = history_->beginAttempt(viewer.userId, lesson.id, mode);
    if (id) attemptId_ = *id;
  }
  const QString stamp = QDateTime::currentDateTimeUtc().toString(QStringLiteral("yyyyMMdd-HHmmss-zzz"));
  QDir().mkpath(dataFolder(QStringLiteral("recordings")));
  recordingPath_ = dataFolder(QStringLiteral("recordings")) +
                   QStringLiteral("/%1-%2-%3.msrec").arg(lesson.id, stamp).arg(attemptId_);
  runner_->setRecordingFile(recordingPath_);

  // the page
  title_->setText(QStringLiteral("<h3>%1</h3>").arg(lesson.title.in(language).toHtmlEscaped()));
  mode_->setText(mode == assessment::AttemptMode::Learn ? tr("Learn mode: follow the marks.")
                                                        : tr("Test mode: graded, no hints."));
  steps_->clear();
  for (const lesson::Step& s : lesson.steps) steps_->addItem(s.instruction.in(language));
  status_->setText(attemptId_ == 0 ? tr("This attempt is not stored (no history).") : QString());
  stepsDone_ = 0;
  eventsSeen_ = 0;
  graspNoted_ = false;
  restPositions_.clear();
  maxDisplacementMm_ = 0.0;
  finish_->setEnabled(true);
  abandon_->setEnabled(true);
  viewport_->setRunner(runner_.get());
  viewport_->sceneChanged();
  viewport_->setGuides(mode == assessment::AttemptMode::Learn ? viewportGuides(lesson, {}) : std::vector<Guide>{});
  applyViewSettings();
  active_ = true;
  updateProgress();
  return true;
}

void AttemptPage::applyViewSettings() {
  const QStringList modes = {QStringLiteral("mono"), QStringLiteral("quad"), QStringLiteral("anaglyph"),
                             QStringLiteral("side")};
  const int mode = static_cast<int>(modes.indexOf(settings::Tunables::value(settings::stereoKey()).toString()));
  viewport_->setStereoMode(static_cast<StereoMode>(std::max(0, mode)));
}

void AttemptPage::startLive() {
  if (!active_) return;
  replaying_ = false;
  if (const sim::SceneDef* def = runner_->sceneDef()) manual_->placeTools(*def);
  viewport_->setManualSource(manual_);
  manual_->start();
  runner_->start();
  progressTimer_->start();
  viewport_->setFocus();
}

void AttemptPage::replay(std::vector<sim::InputFrame> frames, bool finishAtEnd) {
  if (!active_) return;
  manual_->stop();
  viewport_->setManualSource(nullptr);
  // a fresh scene stepped deterministically, recorded from its first frame
  sim::SceneError error;
  if (!runner_->load(scenePath_, sim::StepMode::Deterministic, &error)) return;
  runner_->setRecordingFile(recordingPath_);
  viewport_->sceneChanged();
  restPositions_.clear();
  eventsSeen_ = 0;
  graspNoted_ = false;
  replaying_ = true;
  finishAtEnd_ = finishAtEnd;
  status_->setText(tr("Replaying a recording…"));
  progressTimer_->start();
  runner_->replay(std::move(frames));
}

void AttemptPage::stopRunning() {
  progressTimer_->stop();
  manual_->stop();
  runner_->stop();
  replaying_ = false;
}

void AttemptPage::abandon() {
  if (!active_) return;
  stopRunning();
  active_ = false;
}

void AttemptPage::updateProgress() {
  if (const auto snapshot = runner_->latestSnapshot()) {
    if (restPositions_.empty()) restPositions_ = snapshot->tissuePositions;
    const std::vector<float>& p = snapshot->tissuePositions;
    for (std::size_t i = 0; i + 2 < p.size() && i + 2 < restPositions_.size(); i += 3) {
      const double dx = p[i] - restPositions_[i], dy = p[i + 1] - restPositions_[i + 1], dz = p[i + 2] - restPositions_[i + 2];
      maxDisplacementMm_ = std::max(maxDisplacementMm_, std::sqrt(dx * dx + dy * dy + dz * dz));
    }
  }
  const std::vector<sim::SceneEvent> events = runner_->events();
  noteGrasps(events);
  const lesson::AttemptFacts facts = lesson::collectFacts(events, runner_->pierces(), maxDisplacementMm_);
  const int done = lesson::stepsDone(lesson_, facts);
  for (int i = 0; i < steps_->count(); ++i) {
    QListWidgetItem* item = steps_->item(i);
    const QString text = lesson_.steps[static_cast<std::size_t>(i)].instruction.in(language_);
    item->setText((i < done ? QStringLiteral("✔ ") : i == done ? QStringLiteral("➜ ") : QStringLiteral("   ")) + text);
    item->setForeground(i < done ? QColor(0x1b, 0x7f, 0x3a) : palette().color(QPalette::Text));
  }
  if (done != stepsDone_ && attemptMode_ == assessment::AttemptMode::Learn)
    viewport_->setGuides(viewportGuides(lesson_, lesson::guidesHit(lesson_, facts, 0.1)));
  stepsDone_ = done;
  if (done == static_cast<int>(lesson_.steps.size()) && !replaying_)
    status_->setText(tr("Every step is done: finish the attempt when you are ready."));
}

void AttemptPage::noteGrasps(const std::vector<sim::SceneEvent>& events) {
  if (events.size() < eventsSeen_) eventsSeen_ = 0;  // a new scene
  for (std::size_t i = eventsSeen_; i < events.size(); ++i) {
    const sim::SceneEvent& e = events[i];
    if (e.kind == sim::SceneEventKind::GraspEmpty) {
      status_->setText(e.hand == static_cast<int>(sim::Hand::Left)
                           ? tr("The left forceps closed on nothing: nothing lay between its jaws.")
                           : tr("The right forceps closed on nothing: nothing lay between its jaws."));
      graspNoted_ = true;
    } else if (graspNoted_ && (e.kind == sim::SceneEventKind::GrabTissue || e.kind == sim::SceneEventKind::GripSuture)) {
      status_->clear();
      graspNoted_ = false;
    }
  }
  eventsSeen_ = events.size();
}

void AttemptPage::finish() {
  if (!active_) return;
  updateProgress();
  stopRunning();  // finishes the recording file
  active_ = false;
  finish_->setEnabled(false);
  abandon_->setEnabled(false);
  status_->setText(tr("Scoring…"));

  // the graded replay runs off the GUI thread; its result comes back queued
  const std::string scene = scenePath_.toStdString();
  const std::string recording = recordingPath_.toStdString();
  const assessment::Rubric rubric = rubric_;
  AttemptResult base;
  base.lessonIndex = lessonIndex_;
  base.mode = attemptMode_;
  base.attemptId = attemptId_;
  base.recordingPath = recordingPath_;
  if (const sim::SceneDef* def = runner_->sceneDef())
    for (const sim::SceneVessel& v : def->vessels) base.vessels.push_back(v.def);
  if (scoring_.joinable()) scoring_.join();
  // a std::thread: joining it is a synchronisation ThreadSanitizer sees (QThread::wait() is not)
  scoring_ = std::thread([this, scene, recording, rubric, base] {
    AttemptResult result = base;
    auto replayed = assessment::replayAttempt(scene, recording);
    if (auto* attempt = std::get_if<assessment::Attempt>(&replayed)) {
      result.score = assessment::scoreAttempt(*attempt, rubric);
      result.pierces = attempt->pierces;
      result.scored = true;
    }
    QMetaObject::invokeMethod(this, [this, result] { scored(result); }, Qt::QueuedConnection);
  });
}

void AttemptPage::scored(const AttemptResult& scoredResult) {
  AttemptResult result = scoredResult;
  if (!result.scored) result.error = tr("The recording %1 could not be replayed for scoring.").arg(result.recordingPath);
  if (result.scored && result.attemptId != 0) {
    QFile file(result.recordingPath);
    const QByteArray bytes = file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
    result.stored = history_->finishAttempt(result.attemptId, result.score, bytes);
    if (!result.stored)
      result.error = tr("The score could not be stored (%1).").arg(history_->lastError().driverMessage);
  }
  status_->clear();
  Q_EMIT finished(result);
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
