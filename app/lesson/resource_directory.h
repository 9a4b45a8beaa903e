#pragma once
// Where the programs find the files they ship with: lessons, scenes, rubrics, meshes and the
// recorded stitch. One rule serves an installed package and a build tree alike: the folder
// `share/microsim` beside the executable's folder (`/usr/bin/microsim` reads
// `/usr/share/microsim`). The build tree mirrors that layout: configuring links
// `<build dir>/share/microsim` to the source tree's `resources/`, so `build/release/app/microsim`
// and the test executables in `build/release/tests` read the sources' files. No path of the
// build machine is compiled in, so an installed program never reads a source tree by accident.
#include <QString>

namespace microsim::lesson {

/// The shipped resources' folder for a program in `executableDir`: `overrideDir` when it is
/// not empty (the user's choice, returned as given), else `<executableDir>/../share/microsim`,
/// cleaned. Pure: the folder is named whether or not it exists, so that a missing install is
/// reported with the place that was looked at.
QString resourceDirectoryFor(const QString& overrideDir, const QString& executableDir);

/// This program's shipped resources: `$MICROSIM_RESOURCES` when set, else beside the executable
/// as resourceDirectoryFor() says.
QString resourceDirectory();

}  // namespace microsim::lesson
