// `microsim-cli export --scene FILE | --lattice N [--json OUT]`: the network exactly as
// the solver sees it once the scene is built — nodes with masses, links with rest length,
// stiffness and alive flag, fixed nodes, control nodes with their targets, surface
// triangles and where each declared object landed. Prints a summary; --json writes it all.
#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/output_file.h"
#include "cli/spring_scene_input.h"

#include <nlohmann/json.hpp>

namespace microsim::cli {

namespace {

nlohmann::json vec3(const sim::Vec3& v) {
  return {v.x(), v.y(), v.z()};
}

nlohmann::json networkJson(const sim::SpringScene& scene) {
  const sim::SpringModel& m = scene.model;
  nlohmann::json doc;

  // nodes and their masses, in the model's order
  nlohmann::json nodes = nlohmann::json::array();
  nlohmann::json masses = nlohmann::json::array();
  for (int i = 0; i < m.nodeCount(); ++i) {
    nodes.push_back(vec3(m.restPositions().col(i)));
    masses.push_back(m.mass(i));
  }
  doc["nodes"] = std::move(nodes);
  doc["masses"] = std::move(masses);

  // every link, cut ones included and flagged
  nlohmann::json links = nlohmann::json::array();
  for (const sim::Link& l : m.links()) {
    nlohmann::json j = {{"a", l.a}, {"b", l.b}, {"rest", l.rest}, {"k", l.k}, {"alive", l.alive}};
    if (l.law != sim::StiffnessLaw::Constant) {
      j["law"] = l.law == sim::StiffnessLaw::Stiffening ? "stiffening" : "exponential";
      j["gain"] = l.gain;
    }
    links.push_back(std::move(j));
  }
  doc["links"] = std::move(links);
  doc["fixed"] = m.fixedNodes();

  nlohmann::json controls = nlohmann::json::array();
  for (int c = 0; c < scene.controls.size(); ++c)
    controls.push_back(
        {{"node", scene.controls.nodes[c]}, {"target", vec3(scene.controls.targets.col(c))}});
  doc["controls"] = std::move(controls);

  nlohmann::json triangles = nlohmann::json::array();
  for (const auto& t : m.triangles()) triangles.push_back({t[0], t[1], t[2]});
  doc["triangles"] = std::move(triangles);
  doc["gravity"] = vec3(m.gravity);

  nlohmann::json objects = nlohmann::json::array();
  for (const sim::SceneObject& o : scene.objects)
    objects.push_back({{"type", o.type},
                       {"name", o.name},
                       {"first_node", o.firstNode},
                       {"node_count", o.nodeCount},
                       {"first_link", o.firstLink},
                       {"link_count", o.linkCount},
                       {"first_triangle", o.firstTriangle},
                       {"triangle_count", o.triangleCount}});
  doc["objects"] = std::move(objects);
  return doc;
}

struct ExportOptions {
  SceneInputOptions input;
  QCommandLineOption json{QStringLiteral("json"), Cli::tr("Write the network as JSON to <file>."), QStringLiteral("file")};

  QString usage() const { return Cli::tr("Usage: microsim-cli export --scene FILE | --lattice N [--json FILE]"); }
  void declare(CommandLine& line) const { line.addOptions(input.all() << json); }
};

// load → report
int exportNetwork(const CommandLine& line, const ExportOptions& options) {
  // load
  int code = kExitOk;
  const std::optional<sim::SpringScene> scene = readSceneInput(line, options.input, code);
  if (!scene) return code;

  // report: the summary, the whole network as JSON
  const sim::SpringModel& m = scene->model;
  QTextStream& out = line.io().out;
  const auto row = [&out](const QString& label, long long value) {
    out << "  " << label.leftJustified(12) << value << '\n';
  };
  row(Cli::tr("objects"), static_cast<long long>(scene->objects.size()));
  row(Cli::tr("nodes"), m.nodeCount());
  row(Cli::tr("links"), m.aliveLinkCount());
  row(Cli::tr("fixed"), static_cast<long long>(m.fixedNodes().size()));
  row(Cli::tr("controls"), scene->controls.size());
  row(Cli::tr("triangles"), static_cast<long long>(m.triangles().size()));
  if (!line.isSet(options.json)) return kExitOk;
  return writeCommandOutput(line, line.value(options.json),
                            QByteArray::fromStdString(networkJson(*scene).dump() + "\n"));
}

}  // namespace

int runExport(const QStringList& args, Streams& io) {
  return runCommand(QStringLiteral("export"), args, io, &exportNetwork);
}

}  // namespace microsim::cli
