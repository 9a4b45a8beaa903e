#pragma once
// `microsim --check-start`: the app starts as it always does — the history opened, the main
// window built with the shipped lessons and shown — and quits once the window has been drawn.
// It exits 0 only when the window drew, every lesson file in the lessons folder loaded and the
// history opened, so a package installed without its resources, its SQLite driver or a display
// plugin fails with the reason on stderr. The package test (scripts/package-test.sh) runs it
// on the installed program under Xvfb.
#include "microsim/assessment/storage/history_database.h"

#include <QString>

namespace microsim::gui {

class MainWindow;

/// Runs the event loop until a widget of `window` (already shown) has been painted or
/// `timeoutMs` passed, then checks the lessons and the `history` opened from `databasePath`.
/// Prints what started on stdout and each failure on stderr; returns the exit code (0 or 1).
int checkStart(const MainWindow& window, const assessment::DatabaseStatus& history, const QString& databasePath,
               int timeoutMs = 30000);

}  // namespace microsim::gui
