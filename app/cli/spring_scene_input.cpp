#include "cli/spring_scene_input.h"

#include "microsim/sim/mesh/lattice.h"

#include <cmath>
#include <utility>

namespace microsim::cli {

namespace {

QString kindText(sim::SceneErrorKind kind) {
  using K = sim::SceneErrorKind;
  switch (kind) {
    case K::FileNotFound:
      return Cli::tr("cannot open the scene file");
    case K::MalformedJson:
      return Cli::tr("not valid JSON");
    case K::WrongType:
      return Cli::tr("wrong type or length");
    case K::MissingField:
      return Cli::tr("required field missing");
    case K::UnknownField:
      return Cli::tr("unknown field");
    case K::UnknownObjectType:
      return Cli::tr("unknown object type");
    case K::IndexOutOfRange:
      return Cli::tr("node index out of range");
    case K::SelfLink:
      return Cli::tr("link joins a node to itself");
    case K::NegativeValue:
      return Cli::tr("value must not be negative");
    case K::NonFinite:
      return Cli::tr("number is not finite");
    case K::DuplicateControl:
      return Cli::tr("node is controlled twice");
    case K::InvalidValue:
      return Cli::tr("value out of range");
    case K::MeshImport:
      return Cli::tr("cannot import the surface mesh");
  }
  return {};
}

QString meshText(const sim::MeshImportError& e) {
  using K = sim::MeshImportErrorKind;
  QString text;
  switch (e.kind) {
    case K::FileNotFound:
      text = Cli::tr("file not found");
      break;
    case K::Unreadable:
      text = Cli::tr("unreadable");
      break;
    case K::NoTriangles:
      text = Cli::tr("no triangles");
      break;
    case K::NonFiniteCoords:
      text = Cli::tr("non-finite coordinates");
      break;
    case K::BadOptions:
      text = Cli::tr("bad import options");
      break;
  }
  if (!e.detail.empty()) text += QStringLiteral(": ") + QString::fromStdString(e.detail).trimmed();
  return text;
}

}  // namespace

QString describeSceneError(const sim::SceneError& error) {
  QString where = QString::fromStdString(error.file);
  if (error.line > 0) where += QStringLiteral(":%1:%2").arg(error.line).arg(error.column);
  QString text = where + QStringLiteral(": ") + kindText(error.kind);
  if (error.meshError) text += QStringLiteral(" (") + meshText(*error.meshError) + QLatin1Char(')');
  if (!error.field.empty())
    text += QLatin1Char(' ') + Cli::tr("(field %1)").arg(QString::fromStdString(error.field));
  return text;
}

std::optional<sim::SpringScene> readSceneInput(const CommandLine& line, const SceneInputOptions& options,
                                               int& exitCode) {
  exitCode = kExitUsage;
  const bool haveScene = line.isSet(options.scene);
  const bool haveLattice = line.isSet(options.lattice);
  if (haveScene == haveLattice) {
    line.usageError(Cli::tr("give exactly one of --scene FILE and --lattice N"));
    return std::nullopt;
  }
  if (line.isSet(options.stiffness) && !haveLattice) {
    line.usageError(Cli::tr("--stiffness applies to --lattice only"));
    return std::nullopt;
  }

  // a scene file: its errors are the file's fault, not the command line's
  if (haveScene) {
    sim::SceneLoad load = sim::loadSpringScene(line.value(options.scene).toStdString());
    if (auto* e = std::get_if<sim::SceneError>(&load)) {
      exitCode = line.failure(describeSceneError(*e));
      return std::nullopt;
    }
    exitCode = kExitOk;
    return std::move(std::get<sim::SpringScene>(load));
  }

  // the paper's lattice protocol
  bool ok = false;
  const int n = line.value(options.lattice).toInt(&ok);
  if (!ok || n < 2 || n > 200) {
    line.usageError(Cli::tr("--lattice wants a whole number from 2 to 200, not '%1'").arg(line.value(options.lattice)));
    return std::nullopt;
  }
  double k = 10.0;
  if (line.isSet(options.stiffness)) {
    k = line.value(options.stiffness).toDouble(&ok);
    if (!ok || !(k >= 0.0) || !std::isfinite(k)) {
      line.usageError(Cli::tr("--stiffness wants a number ≥ 0, not '%1'").arg(line.value(options.stiffness)));
      return std::nullopt;
    }
  }
  sim::SpringScene scene;
  scene.model = sim::latticeBox(n, k);
  const int top = sim::latticeTopMiddle(n);
  scene.controls.add(top, scene.model.restPositions().col(top) + sim::Vec3(0, 0, 1));
  sim::SceneObject info;
  info.type = "lattice";
  info.nodeCount = scene.model.nodeCount();
  info.linkCount = scene.model.linkCount();
  info.triangleCount = static_cast<int>(scene.model.triangles().size());
  scene.objects.push_back(info);
  exitCode = kExitOk;
  return scene;
}

}  // namespace microsim::cli
