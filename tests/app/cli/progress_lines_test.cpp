// ProgressLines: every step a line when steps are far apart, at most one line per gap, the
// latest step printed once its gap is over, a waiting step dropped when the work ends.
#include "cli/progress_lines.h"

#include <QIODevice>
#include <QStringList>
#include <QTextStream>

#include <gtest/gtest.h>

#include <chrono>
#include <condition_variable>
#include <mutex>

namespace microsim::cli {
namespace {

using namespace std::chrono_literals;

// What the lines were written to, readable while the watcher thread writes.
class Sink : public QIODevice {
 public:
  Sink() { open(QIODevice::WriteOnly); }

  QString text() {
    const std::lock_guard lock(mutex_);
    return text_;
  }
  /// Waits (10 s at most) until `part` has been written.
  bool waitFor(const QString& part) {
    std::unique_lock lock(mutex_);
    return written_.wait_for(lock, 10s, [&] { return text_.contains(part); });
  }

 protected:
  qint64 readData(char*, qint64) override { return -1; }
  qint64 writeData(const char* data, qint64 size) override {
    {
      const std::lock_guard lock(mutex_);
      text_ += QString::fromUtf8(data, static_cast<int>(size));
    }
    written_.notify_all();
    return size;
  }

 private:
  std::mutex mutex_;
  std::condition_variable written_;
  QString text_;
};

void stepThrough(ProgressLines& lines, const QStringList& steps) {
  for (const QString& s : steps) lines.step(s);
}

TEST(ProgressLines, WithNoGapEveryStepIsALineAtOnce) {
  Sink sink;
  QTextStream err(&sink);
  ProgressLines lines(err, 0s);
  stepThrough(lines, {QStringLiteral("a"), QStringLiteral("b"), QStringLiteral("c")});
  EXPECT_EQ(sink.text().toStdString(), "a\nb\nc\n");
}

TEST(ProgressLines, AStepWithinTheGapWaitsAndIsDroppedWhenTheWorkEnds) {
  Sink sink;
  {
    QTextStream err(&sink);
    ProgressLines lines(err, 1h);
    stepThrough(lines, {QStringLiteral("a"), QStringLiteral("b")});
    EXPECT_EQ(sink.text().toStdString(), "a\n");
  }
  EXPECT_EQ(sink.text().toStdString(), "a\n");
}

TEST(ProgressLines, TheLatestWaitingStepIsPrintedOnceTheGapIsOver) {
  Sink sink;
  QTextStream err(&sink);
  ProgressLines lines(err, 20ms);
  stepThrough(lines, {QStringLiteral("a"), QStringLiteral("b"), QStringLiteral("c")});
  ASSERT_TRUE(sink.waitFor(QStringLiteral("c\n"))) << sink.text().toStdString();
  // "b" too if this thread stalled for a gap between the steps; the first and the latest always
  EXPECT_TRUE(sink.text().startsWith(QStringLiteral("a\n"))) << sink.text().toStdString();
  EXPECT_TRUE(sink.text().endsWith(QStringLiteral("c\n"))) << sink.text().toStdString();
}

}  // namespace
}  // namespace microsim::cli
