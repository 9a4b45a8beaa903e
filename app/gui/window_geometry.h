#pragma once
// Keeping the main window on its screen. A geometry saved on a larger screen (or grown by a
// page that once needed more room) must not come back taller or wider than the screen it is
// restored on: a window 869 lines tall on an 800-line screen hides its bottom row, the
// sign-in buttons. fitInside is the pure rule; fitToScreen applies it to a window.

#include <QRect>

class QWidget;

namespace microsim::gui {

/// `frame` (a window's outer rectangle) shrunk to at most `available`'s size and moved so
/// that it lies inside `available`; unchanged when it already does.
QRect fitInside(const QRect& frame, const QRect& available);

/// Fits `window`'s frame into the available geometry (without panels and docks) of the
/// screen its centre is on (else its own screen), keeping the decoration's margins.
void fitToScreen(QWidget& window);

}  // namespace microsim::gui
