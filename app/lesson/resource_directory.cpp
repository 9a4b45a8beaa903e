#include "lesson/resource_directory.h"

#include <QCoreApplication>
#include <QDir>

namespace microsim::lesson {

QString resourceDirectoryFor(const QString& overrideDir, const QString& executableDir) {
  if (!overrideDir.isEmpty()) return overrideDir;
  return QDir::cleanPath(QDir(executableDir).filePath(QStringLiteral("../share/microsim")));
}

QString resourceDirectory() {
  return resourceDirectoryFor(qEnvironmentVariable("MICROSIM_RESOURCES"), QCoreApplication::applicationDirPath());
}

}  // namespace microsim::lesson
