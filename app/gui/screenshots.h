#pragma once
// `microsim --screenshot DIR`: a PNG of each main screen, for the README and review —
// sign-in, the lesson list, an attempt at lesson 2 in Learn mode (the shipped stitch replayed
// part way, so the tools, the needle and the guides show), its results after the whole
// stitch, and the settings dialog. The screens are made in a throw-away history (a demo
// trainee in a temporary folder); the user's own history is never touched.
#include <QString>
#include <QStringList>

#include <functional>

class QWidget;

namespace microsim::gui {

/// Called with each screen as it is captured, laid out at its size (the PNG's file name and
/// the window or dialog), e.g. by a test that checks every label fits.
using ScreenInspector = std::function<void(const QString& fileName, QWidget& screen)>;

/// Writes the screens to `directory` at `width`×`height`; returns the files written, empty on
/// failure (with `error` saying why).
QStringList writeScreenshots(const QString& directory, QString* error = nullptr, int width = 1280,
                             int height = 800, const ScreenInspector& inspect = {});

}  // namespace microsim::gui
