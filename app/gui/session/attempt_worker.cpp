#include "gui/session/attempt_worker.h"

#include "microsim/assessment/scoring/attempt.h"
#include "microsim/assessment/storage/attempt_store.h"
#include "microsim/assessment/storage/score_store.h"
#include "microsim/sim/scene/recording.h"

#include <QFile>
#include <QThread>

#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <variant>

namespace microsim::gui {

namespace {

AttemptProblem historyProblem(AttemptFailure failure, const QString& driverMessage) {
  AttemptProblem p;
  p.failure = failure;
  p.driverMessage = driverMessage;
  return p;
}

}  // namespace

AttemptWorker::AttemptWorker(QString historyLocation, qint64 traineeId, QString lesson, assessment::AttemptMode mode)
    : location_(std::move(historyLocation)), traineeId_(traineeId), lesson_(std::move(lesson)), mode_(mode) {}

AttemptWorker::~AttemptWorker() = default;

void AttemptWorker::begin() {
  if (location_.isEmpty()) {
    Q_EMIT begun(0);
    return;
  }
  history_ = std::make_unique<assessment::HistoryDatabase>();
  const assessment::DatabaseStatus opened = history_->open(location_);
  if (!opened.ok()) {
    Q_EMIT failed(historyProblem(AttemptFailure::HistoryUnavailable, opened.driverMessage));
    Q_EMIT begun(0);
    return;
  }
  assessment::AttemptStore attempts(*history_);
  const std::optional<qint64> id = attempts.begin(traineeId_, lesson_, mode_);
  if (!id) Q_EMIT failed(historyProblem(AttemptFailure::HistoryUnavailable, attempts.lastError().driverMessage));
  attemptId_ = id.value_or(0);
  Q_EMIT begun(attemptId_);
}

void AttemptWorker::score(const AttemptScoring& request) {
  AttemptResult result = request.base;
  result.attemptId = attemptId_;

  // the recording's bytes: replayed to grade it, and stored as they are
  QFile file(request.recordingPath);
  const QByteArray bytes = file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
  sim::Recording recording;
  const sim::RecordingStatus read = sim::decodeRecording(
      std::span(reinterpret_cast<const std::uint8_t*>(bytes.constData()), static_cast<std::size_t>(bytes.size())),
      recording);
  std::optional<assessment::Attempt> attempt;
  if (read.ok() || read.error == sim::RecordingError::Truncated) {
    auto replayed = assessment::replayAttempt(request.scene, recording, !read.ok());
    if (auto* a = std::get_if<assessment::Attempt>(&replayed)) attempt = std::move(*a);
  }
  if (!attempt) {
    AttemptProblem problem;
    problem.failure = AttemptFailure::RecordingUnreadable;
    problem.file = request.recordingPath;
    result.problem = problem;
    Q_EMIT scored(result);
    return;
  }
  result.score = assessment::scoreAttempt(*attempt, request.rubric);
  result.pierces = attempt->pierces;
  result.scored = true;

  if (history_ && attemptId_ != 0) {
    assessment::ScoreStore scores(*history_);
    result.stored = scores.finish(attemptId_, result.score, bytes);
    if (!result.stored) result.problem = historyProblem(AttemptFailure::ScoreNotStored, scores.lastError().driverMessage);
  }
  Q_EMIT scored(result);
}

void AttemptWorker::close() { thread()->quit(); }

void AttemptWorker::abandon() {
  if (!history_ || attemptId_ == 0) {
    Q_EMIT abandoned(false);
    return;
  }
  assessment::AttemptStore attempts(*history_);
  const bool stored = attempts.abandon(attemptId_);
  if (!stored) Q_EMIT failed(historyProblem(AttemptFailure::AbandonNotStored, attempts.lastError().driverMessage));
  Q_EMIT abandoned(stored);
}

}  // namespace microsim::gui
