#include "gui/pages/trainee_progress_loader.h"

#include "gui/review/review_data.h"

#include "microsim/assessment/storage/attempt_detail.h"
#include "microsim/assessment/storage/attempt_store.h"

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
    : QObject(parent), reader_(std::move(historyLocation)) {
  qRegisterMetaType<TraineeProgress>();
}

void TraineeProgressLoader::load(const assessment::Viewer& viewer, const QString& lesson) {
  reader_.read<TraineeProgress>(
      [viewer, lesson](assessment::HistoryDatabase& history) { return readTraineeProgress(history, viewer, lesson); },
      [lesson](const QString& why) {
        return TraineeProgress{lesson, {}, {}, {assessment::HistoryError::NotOpen, why}};
      },
      [this](const TraineeProgress& progress) { Q_EMIT loaded(progress); });
}

}  // namespace microsim::gui
