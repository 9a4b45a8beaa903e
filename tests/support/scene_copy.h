#pragma once
// A copy of the shipped scene that a test may move, edit or delete: FOLDER/scenes/NAME, with
// the mesh it names at FOLDER/meshes (the scene names it as ../meshes/forceps_jaw.obj).
#include "support/shipped_files.h"

#include <QDir>
#include <QFile>
#include <QString>

namespace microsim::testing {

/// The copy's path, or an empty string when a file could not be copied.
inline QString copyShippedScene(const QString& folder, const QString& name) {
  const QDir root(folder);
  if (!root.mkpath(QStringLiteral("scenes")) || !root.mkpath(QStringLiteral("meshes"))) return {};
  const QString mesh = root.filePath(QStringLiteral("meshes/forceps_jaw.obj"));
  if (!QFile::exists(mesh) && !QFile::copy(kSourceRoot + QStringLiteral("/resources/meshes/forceps_jaw.obj"), mesh))
    return {};
  const QString scene = root.filePath(QStringLiteral("scenes/") + name);
  return QFile::copy(kShippedScene, scene) ? scene : QString();
}

}  // namespace microsim::testing
