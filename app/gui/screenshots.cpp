#include "gui/screenshots.h"

#include "gui/main_window.h"
#include "gui/viewport.h"

#include <QDir>
#include <QEventLoop>
#include <QPixmap>
#include <QTimer>

namespace microsim::gui {

namespace {

// spin the event loop until the viewport has drawn a frame (or a generous deadline passes)
bool waitForFrame(Viewport& viewport) {
  if (viewport.framesDrawn() > 0) return true;
  QEventLoop loop;
  QObject::connect(&viewport, &Viewport::frameDrawn, &loop, &QEventLoop::quit);
  QTimer::singleShot(10000, &loop, &QEventLoop::quit);
  loop.exec();
  return viewport.framesDrawn() > 0;
}

}  // namespace

QStringList writeScreenshots(MainWindow& window, const QString& directory) {
  if (!QDir().mkpath(directory)) return {};
  window.show();
  if (!waitForFrame(*window.viewport())) return {};
  const QString file = QDir(directory).filePath(QStringLiteral("main-window.png"));
  if (!window.grab().save(file)) return {};
  return {file};
}

}  // namespace microsim::gui
