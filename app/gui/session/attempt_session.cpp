#include "gui/session/attempt_session.h"

#include "gui/session/attempt_worker.h"
#include "gui/simulation_runner.h"
#include "lesson/progress.h"

#include <QDateTime>
#include <QDir>
#include <QJsonObject>
#include <QTimer>

#include <algorithm>
#include <cmath>
#include <utility>

namespace microsim::gui {

AttemptSession::AttemptSession(QObject* parent)
    : QObject(parent), runner_(std::make_unique<SimulationRunner>()) {
  qRegisterMetaType<microsim::gui::AttemptResult>();
  qRegisterMetaType<microsim::gui::AttemptProblem>();
  qRegisterMetaType<microsim::gui::AttemptProgress>();
  qRegisterMetaType<microsim::gui::AttemptScoring>();
  progressTimer_ = new QTimer(this);
  progressTimer_->setInterval(100);
  connect(progressTimer_, &QTimer::timeout, this, &AttemptSession::poll);
  connect(runner_.get(), &SimulationRunner::replayFinished, this, [this] {
    if (!replaying_ || state_ != State::Active) return;
    if (finishAtEnd_) {
      finish();
      return;
    }
    progressTimer_->stop();
    poll();
    Q_EMIT replayEnded();
  });
}

AttemptSession::~AttemptSession() {
  stopRunning();
  shutDownWorker();
}

bool AttemptSession::prepare(const AttemptSetup& setup, AttemptProblem* problem) {
  if (state_ != State::Idle || !loadLesson(setup, problem)) return false;
  setup_ = setup;
  startRecording();
  startWorker();
  state_ = State::Active;
  poll();
  return true;
}

bool AttemptSession::loadLesson(const AttemptSetup& setup, AttemptProblem* problem) {
  // the rubric, and the scene with the solver settings
  const auto rubric = assessment::loadRubric(setup.lesson.rubricPath.toStdString());
  if (const auto* e = std::get_if<assessment::RubricError>(&rubric)) {
    *problem = {AttemptFailure::RubricUnreadable, QString::fromStdString(e->file), QString::fromStdString(e->field),
                e->line, {}};
    return false;
  }
  rubric_ = std::get<assessment::Rubric>(rubric);
  sim::SceneDefLoad scene = sim::loadSceneDef(setup.lesson.scenePath.toStdString());
  if (const auto* e = std::get_if<sim::SceneError>(&scene)) {
    *problem = {AttemptFailure::SceneUnreadable, setup.lesson.scenePath, QString::fromStdString(e->field), e->line, {}};
    return false;
  }
  def_ = std::move(std::get<sim::SceneDef>(scene));
  if (!settings::applySolverOverride(def_, setup.solver)) {
    *problem = {AttemptFailure::UnknownSolver, setup.lesson.scenePath, setup.solver.solver, 0, {}};
    return false;
  }
  return true;
}

void AttemptSession::startRecording() {
  // stepped deterministically, live too: the frames the attempt consumed replay to the very
  // states the trainee saw, and the score is computed on those (a slow step makes the scene
  // lag the hand rather than show a tissue the score will not see)
  runner_->load(def_, sim::StepMode::Deterministic);
  const QString stamp = QDateTime::currentDateTimeUtc().toString(QStringLiteral("yyyyMMdd-HHmmss-zzz"));
  QDir().mkpath(setup_.recordingFolder);
  recordingPath_ = QDir(setup_.recordingFolder).filePath(QStringLiteral("%1-%2.msrec").arg(setup_.lesson.id, stamp));
  // the recording says which lesson it is and, when the settings changed it, the solver
  QJsonObject metadata{{QStringLiteral("lesson"), setup_.lesson.id}};
  if (const QJsonObject solver = settings::solverOverrideJson(def_, setup_.solver); !solver.isEmpty())
    metadata.insert(QStringLiteral("solver"), solver);
  runner_->setRecordingFile(recordingPath_, metadata);
}

void AttemptSession::startWorker() {
  // the attempt in the history, on the worker's thread and connection
  const assessment::Viewer& viewer = setup_.viewer;
  worker_ = new AttemptWorker(viewer.userId != 0 ? setup_.historyLocation : QString(), viewer.userId,
                              setup_.lesson.id, setup_.mode);
  worker_->moveToThread(&thread_);
  connect(&thread_, &QThread::finished, worker_, &QObject::deleteLater);
  requests_ = std::make_unique<AttemptRequests>();
  connect(requests_.get(), &AttemptRequests::begin, worker_, &AttemptWorker::begin);
  connect(requests_.get(), &AttemptRequests::score, worker_, &AttemptWorker::score);
  connect(requests_.get(), &AttemptRequests::abandon, worker_, &AttemptWorker::abandon);
  connect(requests_.get(), &AttemptRequests::close, worker_, &AttemptWorker::close);
  connect(worker_, &AttemptWorker::begun, this, [this](qint64 id) {
    attemptId_ = id;
    Q_EMIT begun(id);
  });
  connect(worker_, &AttemptWorker::scored, this, [this](const AttemptResult& result) {
    state_ = State::Finished;
    Q_EMIT finished(result);
  });
  connect(worker_, &AttemptWorker::abandoned, this, &AttemptSession::abandoned);
  connect(worker_, &AttemptWorker::failed, this, &AttemptSession::failed);
  thread_.setObjectName(QStringLiteral("attempt history"));
  thread_.start();
  Q_EMIT requests_->begin();
}

void AttemptSession::startLive() {
  if (state_ != State::Active) return;
  replaying_ = false;
  runner_->start();
  progressTimer_->start();
}

void AttemptSession::replay(std::vector<sim::InputFrame> frames, bool finishAtEnd) {
  if (state_ != State::Active) return;
  // a fresh scene stepped deterministically, recorded from its first frame
  runner_->load(def_, sim::StepMode::Deterministic);
  restPositions_.clear();
  replaying_ = true;
  finishAtEnd_ = finishAtEnd;
  progressTimer_->start();
  runner_->replay(std::move(frames));
}

void AttemptSession::finish() {
  if (state_ != State::Active) return;
  poll();
  stopRunning();  // finishes the recording file
  state_ = State::Scoring;
  AttemptScoring request{def_, rubric_, recordingPath_, {}};
  request.base.lessonIndex = setup_.lessonIndex;
  request.base.mode = setup_.mode;
  request.base.recordingPath = recordingPath_;
  for (const sim::SceneVessel& v : def_.vessels) request.base.vessels.push_back(v.def);
  Q_EMIT requests_->score(request);
}

void AttemptSession::abandon() {
  if (state_ != State::Active) return;
  stopRunning();
  state_ = State::Abandoned;
  Q_EMIT requests_->abandon();
}

void AttemptSession::stop() {
  stopRunning();
  if (state_ == State::Active) state_ = State::Stopped;
}

void AttemptSession::stopRunning() {
  progressTimer_->stop();
  runner_->stop();
  replaying_ = false;
}

void AttemptSession::shutDownWorker() {
  if (!worker_) return;
  // sent after every request, so each runs before the thread ends; the worker (and the
  // history connection it holds) is deleted on its own thread as it finishes
  Q_EMIT requests_->close();
  thread_.wait();
  worker_ = nullptr;
}

void AttemptSession::poll() {
  if (const auto snapshot = runner_->latestSnapshot()) {
    if (restPositions_.empty()) restPositions_ = snapshot->tissuePositions;
    const std::vector<float>& p = snapshot->tissuePositions;
    for (std::size_t i = 0; i + 2 < p.size() && i + 2 < restPositions_.size(); i += 3) {
      const double dx = p[i] - restPositions_[i], dy = p[i + 1] - restPositions_[i + 1], dz = p[i + 2] - restPositions_[i + 2];
      maxDisplacementMm_ = std::max(maxDisplacementMm_, std::sqrt(dx * dx + dy * dy + dz * dz));
    }
  }
  const lesson::AttemptFacts facts = lesson::collectFacts(runner_->events(), runner_->pierces(), maxDisplacementMm_);
  AttemptProgress now{lesson::stepsDone(setup_.lesson, facts), lesson::guidesHit(setup_.lesson, facts, 0.1),
                      facts.emptyGraspHand, facts.threadCuts, facts.lastCutEndMm, facts.threadTooShortMm};
  if (now == progress_) return;
  progress_ = std::move(now);
  Q_EMIT progressed(progress_);
}

}  // namespace microsim::gui
