#pragma once
// `microsim --screenshot DIR`: a PNG of each main screen, for the README and review.
#include <QString>
#include <QStringList>

namespace microsim::gui {

class MainWindow;

/// Waits (on the event loop, for the viewport's first drawn frame) and writes the
/// screens to `directory`; returns the files written, empty on failure.
QStringList writeScreenshots(MainWindow& window, const QString& directory);

}  // namespace microsim::gui
