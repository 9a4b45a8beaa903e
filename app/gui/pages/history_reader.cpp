#include "gui/pages/history_reader.h"

#include <QThread>

#include <algorithm>
#include <utility>

namespace microsim::gui {

HistoryReader::HistoryReader(QString historyLocation, QObject* parent)
    : QObject(parent), location_(std::move(historyLocation)) {}

HistoryReader::~HistoryReader() {
  for (QThread* thread : running_) {
    thread->wait();
    delete thread;
  }
}

void HistoryReader::start(std::function<void(assessment::HistoryDatabase*, const QString&)> work,
                          std::function<void()> done) {
  const quint64 request = ++latest_;
  // the connection is opened, used and closed on the reading thread
  QThread* thread = QThread::create([location = location_, work = std::move(work)] {
    assessment::HistoryDatabase history;
    const assessment::DatabaseStatus opened = history.open(location);
    work(opened.ok() ? &history : nullptr, opened.driverMessage);
  });
  thread->setObjectName(QStringLiteral("history reader"));
  running_.push_back(thread);
  connect(thread, &QThread::finished, this, [this, thread, request, done = std::move(done)] {
    running_.erase(std::remove(running_.begin(), running_.end(), thread), running_.end());
    thread->deleteLater();
    if (request == latest_) done();
  });
  thread->start();
}

}  // namespace microsim::gui
