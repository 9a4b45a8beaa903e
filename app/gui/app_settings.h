#pragma once
// The keys microsim keeps in QSettings, declared once.
#include <QString>

namespace microsim::gui::settings {

inline QString windowGeometry() { return QStringLiteral("ui/windowGeometry"); }
inline QString windowState() { return QStringLiteral("ui/windowState"); }
inline QString depthOfField() { return QStringLiteral("view/depthOfField"); }
inline QString databasePath() { return QStringLiteral("storage/databasePath"); }

}  // namespace microsim::gui::settings
