#include "gui/settings/scene_overrides.h"

#include "gui/settings/tunables.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace microsim::gui::settings {

SolverOverride solverOverrideFromSettings() {
  return {Tunables::value(solverKey()).toString(), Tunables::value(iterationsKey()).toInt()};
}

namespace {

// file references ("mesh" of a forceps, "file" of a surface-mesh object) made absolute
QJsonValue absolutePaths(const QJsonValue& v, const QDir& base) {
  if (v.isArray()) {
    QJsonArray out;
    for (const QJsonValue& item : v.toArray()) out.append(absolutePaths(item, base));
    return out;
  }
  if (!v.isObject()) return v;
  QJsonObject o = v.toObject();
  for (auto it = o.begin(); it != o.end(); ++it) {
    if ((it.key() == QLatin1String("mesh") || it.key() == QLatin1String("file")) && it.value().isString())
      it.value() = QDir::cleanPath(base.absoluteFilePath(it.value().toString()));
    else
      it.value() = absolutePaths(it.value(), base);
  }
  return o;
}

}  // namespace

QString applySolverOverride(const QString& scenePath, const SolverOverride& override,
                            const QString& folder, QString* error) {
  if (!override.any()) return scenePath;
  QFile in(scenePath);
  if (!in.open(QIODevice::ReadOnly)) {
    if (error) *error = in.errorString();
    return {};
  }
  QJsonParseError parseError;
  const QJsonDocument doc = QJsonDocument::fromJson(in.readAll(), &parseError);
  if (!doc.isObject()) {
    if (error) *error = parseError.errorString();
    return {};
  }
  QJsonObject root = absolutePaths(doc.object(), QFileInfo(scenePath).absoluteDir()).toObject();
  QJsonObject solver = root.value(QStringLiteral("solver")).toObject();
  if (!override.solver.isEmpty() && override.solver != QLatin1String("scene")) {
    // another solver's own parameters would be unknown to it: keep only the budget
    const QJsonValue iterations = solver.value(QStringLiteral("iterations"));
    solver = QJsonObject{{QStringLiteral("name"), override.solver}};
    if (!iterations.isUndefined()) solver.insert(QStringLiteral("iterations"), iterations);
  }
  if (override.iterations > 0) solver.insert(QStringLiteral("iterations"), override.iterations);
  root.insert(QStringLiteral("solver"), solver);

  const QByteArray bytes = QJsonDocument(root).toJson();
  const QString name = QFileInfo(scenePath).completeBaseName() + QLatin1Char('-') +
                       QString::fromLatin1(QCryptographicHash::hash(bytes, QCryptographicHash::Sha1).toHex().left(10)) +
                       QStringLiteral(".json");
  if (!QDir().mkpath(folder)) {
    if (error) *error = folder;
    return {};
  }
  QString path = QDir(folder).filePath(name);
  QFile out(path);
  if (!out.open(QIODevice::WriteOnly) || out.write(bytes) != bytes.size()) {
    if (error) *error = out.errorString();
    return {};
  }
  return path;
}

}  // namespace microsim::gui::settings
