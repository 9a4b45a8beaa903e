#pragma once
// Keeping the main window on its screen. A geometry saved on a larger screen (or grown by a
// page that once needed more room) must not come back taller or wider than the screen it is
// restored on: a window 869 lines tall on an 800-line screen hides its bottom row, the
// sign-in buttons. fitInside is the pure rule; fitToScreen applies it to a window.
//
// The first start, with no geometry saved, opened the window at its size hint: 466 by 348 on
// a 1400 by 1000 screen, the sign-in page behind scroll bars and the microscope's picture the
// size of a stamp. It now opens on most of the screen it is on (firstPlacement), centred.

#include <QRect>
#include <QSize>

class QWidget;

namespace microsim::gui {

/// `frame` (a window's outer rectangle) shrunk to at most `available`'s size and moved so
/// that it lies inside `available`; unchanged when it already does.
QRect fitInside(const QRect& frame, const QRect& available);

/// Fits `window`'s frame into the available geometry (without panels and docks) of the
/// screen its centre is on (else its own screen), keeping the decoration's margins.
void fitToScreen(QWidget& window);

/// Where a window with no saved geometry opens on a screen whose available area is
/// `available`: 85 % of it each way, at most 1600 by 1000 and at least `minimum` (as far as
/// the area allows), centred in it.
QRect firstPlacement(const QRect& available, const QSize& minimum);

/// Puts `window` where firstPlacement says on its screen.
void placeFirstTime(QWidget& window);

}  // namespace microsim::gui
