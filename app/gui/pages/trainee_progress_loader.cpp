#include "gui/pages/trainee_progress_loader.h"

#include "gui/review/review_data.h"

#include "microsim/assessment/storage/attempt_detail.h"
#include "microsim/assessment/storage/attempt_store.h"

#include <QThread>

#include <algorithm>
#include <memory>
#include <utility>

namespace microsim::gui {

TraineeProgress readTraineeProgress(assessment::HistoryDatabase& history, const assessment::Viewer& viewer,
                                    const QString& lesson) {
  TraineeProgress progress;
  progress.lesson = lesson;
  assessment::AttemptStore attempts(history);
  const QList<assessment::AttemptSummary> all = attempts.list(viewer, viewer.userId);
  if (!attempts.lastError().ok()) {
    progress.status = attempts.lastError();
    return progress;
  }
  for (const assessment::AttemptSummary& a : finishedAttempts(all, viewer.userId, lesson)) {
    assessment::HistoryStatus status;
    std::optional<assessment::AttemptDetail> detail = assessment::readAttemptDetail(history, viewer, a.id, &status);
    if (!detail) {
      progress = TraineeProgress{lesson, {}, {}, status};
      return progress;
    }
    progress.finished << a;
    progress.details << std::move(*detail);
  }
  return progress;
}

TraineeProgressLoader::TraineeProgressLoader(QString historyLocation, QObject* parent)
    : QObject(parent), location_(std::move(historyLocation)) {
  qRegisterMetaType<TraineeProgress>();
}

TraineeProgressLoader::~TraineeProgressLoader() {
  for (QThread* thread : running_) {
    thread->wait();
    delete thread;
  }
}

void TraineeProgressLoader::load(const assessment::Viewer& viewer, const QString& lesson) {
  const quint64 request = ++latest_;
  auto result = std::make_shared<TraineeProgress>();
  // the connection is opened, used and closed on the loading thread
  QThread* thread = QThread::create([location = location_, viewer, lesson, result] {
    assessment::HistoryDatabase history;
    const assessment::DatabaseStatus opened = history.open(location);
    if (!opened.ok()) {
      *result = TraineeProgress{lesson, {}, {}, {assessment::HistoryError::NotOpen, opened.driverMessage}};
      return;
    }
    *result = readTraineeProgress(history, viewer, lesson);
  });
  thread->setObjectName(QStringLiteral("trainee progress"));
  running_.push_back(thread);
  connect(thread, &QThread::finished, this, [this, thread, request, result] {
    running_.erase(std::remove(running_.begin(), running_.end(), thread), running_.end());
    thread->deleteLater();
    if (request == latest_) Q_EMIT loaded(*result);
  });
  thread->start();
}

}  // namespace microsim::gui
