#pragma once
// The shipped files that the app's tests open, replay and score, each named once: the default
// scene, the scripted stitch recorded on it, and the single-stitch rubric.
#include <QString>

#include <string>

namespace microsim::testing {

inline const QString kSourceRoot = QStringLiteral(MICROSIM_SOURCE_DIR);
inline const QString kShippedScene = kSourceRoot + QStringLiteral("/resources/scenes/anastomosis.json");
inline const QString kShippedStitch = kSourceRoot + QStringLiteral("/resources/recordings/stitch.msrec");
inline const QString kShippedBackWallCatch =
    kSourceRoot + QStringLiteral("/resources/recordings/back_wall_catch.msrec");
inline const QString kShippedRubric = kSourceRoot + QStringLiteral("/resources/rubrics/03_single_stitch.json");

}  // namespace microsim::testing
