#pragma once
// A signal spy for signals emitted in another thread (the simulation thread, a tracker
// thread). QSignalSpy records through a direct connection, in the emitting thread, while the
// test reads it in its own: a data race that ThreadSanitizer reports. This spy receives the
// signal through a queued connection instead, so every call is recorded in the test's thread,
// in the order it was emitted, whenever the test's event loop runs (wait(), QTRY_*,
// processEvents). A call's arguments are kept as QVariants, as QSignalSpy keeps them.
#include <QEventLoop>
#include <QList>
#include <QObject>
#include <QTimer>
#include <QVariant>

namespace microsim::testing {

class QueuedSignalSpy : public QObject {
 public:
  template <typename Sender, typename Signal>
  QueuedSignalSpy(const Sender* sender, Signal signal) {
    QObject::connect(
        sender, signal, this,
        [this](const auto&... args) { record(QList<QVariant>{QVariant::fromValue(args)...}); },
        Qt::QueuedConnection);
  }

  qsizetype count() const { return calls_.size(); }
  bool isEmpty() const { return calls_.isEmpty(); }
  const QList<QVariant>& at(qsizetype i) const { return calls_.at(i); }
  const QList<QVariant>& first() const { return calls_.first(); }
  const QList<QVariant>& last() const { return calls_.last(); }

  /// Runs the event loop until one more call arrives or `timeoutMs` pass; true if one came.
  bool wait(int timeoutMs = 5000) {
    const qsizetype before = calls_.size();
    QEventLoop loop;
    QTimer timeout;
    timeout.setSingleShot(true);
    QObject::connect(&timeout, &QTimer::timeout, &loop, &QEventLoop::quit);
    timeout.start(timeoutMs);
    waiting_ = &loop;
    loop.exec();
    waiting_ = nullptr;
    return calls_.size() > before;
  }

 private:
  void record(QList<QVariant> arguments) {
    calls_.append(std::move(arguments));
    if (waiting_) waiting_->quit();
  }

  QList<QList<QVariant>> calls_;
  QEventLoop* waiting_ = nullptr;
};

}  // namespace microsim::testing
