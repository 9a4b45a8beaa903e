#pragma once
// Screenshots of the review screens for the README (`microsim --screenshot DIR` calls this):
// the page on demo data in a temporary history — three trainees in two groups, attempts
// scored by the shipped rubrics through the scoring API, an instructor signed in.
#include "gui/screenshots.h"

#include <QString>
#include <QStringList>

namespace microsim::gui {

/// Writes review-grid.png, review-history.png, review-attempt.png and review-end-product.png
/// (an attempt's opened vessel with its errors) to `directory`;
/// returns the files written, empty on failure. Needs a QApplication and a display.
/// `inspect` sees each screen before it is captured.
QStringList writeReviewScreenshots(const QString& directory, const ScreenInspector& inspect = {});

}  // namespace microsim::gui
