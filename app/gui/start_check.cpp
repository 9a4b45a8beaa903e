#include "gui/start_check.h"

#include "gui/main_window.h"
#include "lesson/lesson.h"

#include <QApplication>
#include <QDir>
#include <QEvent>
#include <QEventLoop>
#include <QTimer>
#include <QWidget>

#include <cstdio>

namespace microsim::gui {

namespace {

// ends `loop` at the first paint event of any widget in `window`: the window's contents
// reached the screen, not only its frame
class StartCheckPaintWatcher : public QObject {
 public:
  StartCheckPaintWatcher(const QWidget& window, QEventLoop& loop) : window_(window), loop_(loop) {}
  bool painted() const { return painted_; }

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override {
    if (!painted_ && event->type() == QEvent::Paint && watched->isWidgetType() &&
        static_cast<QWidget*>(watched)->window() == &window_) {
      painted_ = true;
      loop_.quit();
    }
    return false;
  }

 private:
  const QWidget& window_;
  QEventLoop& loop_;
  bool painted_ = false;
};

}  // namespace

int checkStart(const MainWindow& window, const assessment::DatabaseStatus& history, const QString& databasePath,
               int timeoutMs) {
  // the event loop until the first paint, as a start would run it
  QEventLoop loop;
  StartCheckPaintWatcher watcher(window, loop);
  QApplication::instance()->installEventFilter(&watcher);
  QTimer::singleShot(timeoutMs, &loop, &QEventLoop::quit);
  loop.exec();
  QApplication::instance()->removeEventFilter(&watcher);

  QStringList failures;
  if (!watcher.painted())
    failures << QApplication::translate("main", "the main window was not drawn within %1 s").arg(timeoutMs / 1000);

  // every lesson file loaded (a lesson also checks that its scene and rubric exist)
  const QString lessons = lesson::lessonsDirectory();
  const auto files = static_cast<int>(QDir(lessons).entryList({QStringLiteral("*.json")}, QDir::Files).size());
  const auto loaded = static_cast<int>(window.lessons().size());
  if (files == 0)
    failures << QApplication::translate("main", "no lesson files in %1").arg(lessons);
  else if (loaded != files)
    failures << QApplication::translate("main", "%1 of %n lesson file(s) in %2 could be read", nullptr, files).arg(loaded).arg(lessons);

  if (!history.ok()) failures << MainWindow::describe(history, databasePath);

  for (const QString& failure : failures) std::fprintf(stderr, "microsim --check-start: %s\n", qPrintable(failure));
  if (!failures.isEmpty()) return 1;
  std::printf("%s\n", qPrintable(QApplication::translate("main", "microsim started: %n lesson(s) from %1, history %2", nullptr, loaded)
                                     .arg(lessons, databasePath)));
  return 0;
}

}  // namespace microsim::gui
