#include "gui/window_geometry.h"

#include <QGuiApplication>
#include <QScreen>
#include <QWidget>

#include <algorithm>

namespace microsim::gui {

QRect fitInside(const QRect& frame, const QRect& available) {
  QRect fitted = frame;
  fitted.setWidth(std::min(frame.width(), available.width()));
  fitted.setHeight(std::min(frame.height(), available.height()));
  // then slide it in: right and bottom edges first, so that the top-left corner (the title
  // bar) wins when both cannot be met
  if (fitted.right() > available.right()) fitted.moveRight(available.right());
  if (fitted.bottom() > available.bottom()) fitted.moveBottom(available.bottom());
  if (fitted.left() < available.left()) fitted.moveLeft(available.left());
  if (fitted.top() < available.top()) fitted.moveTop(available.top());
  return fitted;
}

void fitToScreen(QWidget& window) {
  const QRect client = window.geometry();
  QScreen* screen = QGuiApplication::screenAt(client.center());
  if (!screen) screen = window.screen();
  if (!screen) return;
  const QRect frame = window.frameGeometry();
  const QRect fitted = fitInside(frame, screen->availableGeometry());
  if (fitted == frame) return;
  // the window manager's decoration around the client area stays as it is
  const QMargins decoration(client.left() - frame.left(), client.top() - frame.top(),
                            frame.right() - client.right(), frame.bottom() - client.bottom());
  window.setGeometry(fitted.marginsRemoved(decoration));
}

QRect firstPlacement(const QRect& available, const QSize& minimum) {
  const QSize most(1600, 1000);
  QSize size(static_cast<int>(0.85 * available.width()), static_cast<int>(0.85 * available.height()));
  size = size.boundedTo(most).expandedTo(minimum).boundedTo(available.size());
  QRect placed(QPoint(0, 0), size);
  placed.moveCenter(available.center());
  return placed;
}

void placeFirstTime(QWidget& window) {
  QScreen* screen = window.screen();
  if (!screen) screen = QGuiApplication::primaryScreen();
  if (!screen) return;
  window.setGeometry(firstPlacement(screen->availableGeometry(), window.minimumSizeHint()));
}

}  // namespace microsim::gui
