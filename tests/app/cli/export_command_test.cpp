// `microsim-cli export` as a user runs it: the network the solver sees, round-tripped.
#include "support/cli_runner.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace {

using microsim::testing::CliRun;
using microsim::testing::runCli;

QJsonObject exportScene(const QStringList& input, const QString& out) {
  const CliRun r = runCli(QStringList{QStringLiteral("export")} + input +
                          QStringList{QStringLiteral("--json"), out});
  EXPECT_EQ(r.exitCode, 0) << r.err.toStdString();
  QFile f(out);
  EXPECT_TRUE(f.open(QIODevice::ReadOnly));
  return QJsonDocument::fromJson(f.readAll()).object();
}

// the export written back as a spring-mesh scene: nodes, links [a, b, k, rest], fixed, controls
QByteArray asScene(const QJsonObject& net) {
  QJsonArray links;
  for (const QJsonValue& v : net.value(QStringLiteral("links")).toArray()) {
    const QJsonObject l = v.toObject();
    links.append(QJsonArray{l.value(QStringLiteral("a")), l.value(QStringLiteral("b")),
                            l.value(QStringLiteral("k")), l.value(QStringLiteral("rest"))});
  }
  const QJsonArray nodes = net.value(QStringLiteral("nodes")).toArray();
  QJsonArray controls;
  for (const QJsonValue& v : net.value(QStringLiteral("controls")).toArray()) {
    const QJsonObject c = v.toObject();
    const QJsonArray target = c.value(QStringLiteral("target")).toArray();
    const QJsonArray rest = nodes.at(c.value(QStringLiteral("node")).toInt()).toArray();
    controls.append(QJsonObject{{QStringLiteral("node"), c.value(QStringLiteral("node"))},
                                {QStringLiteral("displacement"),
                                 QJsonArray{target.at(0).toDouble() - rest.at(0).toDouble(),
                                            target.at(1).toDouble() - rest.at(1).toDouble(),
                                            target.at(2).toDouble() - rest.at(2).toDouble()}}});
  }
  QJsonObject mesh{{QStringLiteral("type"), QStringLiteral("spring-mesh")},
                   {QStringLiteral("nodes"), nodes},
                   {QStringLiteral("links"), links},
                   {QStringLiteral("fixed"), net.value(QStringLiteral("fixed"))},
                   {QStringLiteral("controls"), controls}};
  return QJsonDocument(QJsonObject{{QStringLiteral("objects"), QJsonArray{mesh}}}).toJson();
}

TEST(ExportCommand, LatticeRoundTripsThroughASceneFile) {
  QTemporaryDir dir;
  const QJsonObject first = exportScene({QStringLiteral("--lattice"), QStringLiteral("6")},
                                        dir.filePath(QStringLiteral("a.json")));
  const QJsonArray links = first.value(QStringLiteral("links")).toArray();
  EXPECT_EQ(links.size(), 1440);
  EXPECT_EQ(first.value(QStringLiteral("nodes")).toArray().size(), 216);
  EXPECT_EQ(first.value(QStringLiteral("fixed")).toArray().size(), 36);
  ASSERT_EQ(first.value(QStringLiteral("controls")).toArray().size(), 1);
  const QJsonObject control = first.value(QStringLiteral("controls")).toArray().at(0).toObject();
  EXPECT_EQ(control.value(QStringLiteral("node")).toInt(), 3 + 6 * (3 + 6 * 5));
  EXPECT_EQ(control.value(QStringLiteral("target")).toArray().at(2).toDouble(), 6.0);
  const QJsonObject link = links.at(0).toObject();
  EXPECT_EQ(link.value(QStringLiteral("k")).toDouble(), 10.0);
  EXPECT_EQ(link.value(QStringLiteral("rest")).toDouble(), 1.0);
  EXPECT_TRUE(link.value(QStringLiteral("alive")).toBool());

  // write it back as a spring-mesh scene and export again: the same network
  const QString scenePath = dir.filePath(QStringLiteral("round.json"));
  QFile f(scenePath);
  ASSERT_TRUE(f.open(QIODevice::WriteOnly));
  f.write(asScene(first));
  f.close();
  const QJsonObject second =
      exportScene({QStringLiteral("--scene"), scenePath}, dir.filePath(QStringLiteral("b.json")));
  for (const char* key : {"nodes", "links", "fixed", "controls"})
    EXPECT_EQ(second.value(QLatin1String(key)), first.value(QLatin1String(key))) << key;
}

TEST(ExportCommand, MixedSceneObjectsAndCounts) {
  QTemporaryDir dir;
  const QJsonObject net = exportScene(
      {QStringLiteral("--scene"), QStringLiteral(MICROSIM_TEST_DATA_DIR "/scenes/mixed.json")},
      dir.filePath(QStringLiteral("m.json")));
  const QJsonArray objects = net.value(QStringLiteral("objects")).toArray();
  ASSERT_EQ(objects.size(), 6);
  int links = 0;
  for (const QJsonValue& o : objects)
    links += o.toObject().value(QStringLiteral("link_count")).toInt();
  EXPECT_EQ(net.value(QStringLiteral("links")).toArray().size(), links);
  EXPECT_EQ(objects.at(4).toObject().value(QStringLiteral("type")).toString(),
            QStringLiteral("surface-mesh"));
  EXPECT_EQ(net.value(QStringLiteral("gravity")).toArray().at(2).toDouble(), -9810.0);
  EXPECT_FALSE(net.value(QStringLiteral("triangles")).toArray().isEmpty());

  const CliRun summary = runCli({QStringLiteral("export"), QStringLiteral("--scene"),
                                 QStringLiteral(MICROSIM_TEST_DATA_DIR "/scenes/mixed.json")});
  EXPECT_EQ(summary.exitCode, 0);
  EXPECT_TRUE(summary.out.contains(QStringLiteral("links")));
  EXPECT_TRUE(summary.out.contains(QString::number(links)));
}

// a vessel of the wall material (as the shipped scenes declare it) keeps its law and exponent
// in the export
TEST(ExportCommand, TheWallMaterialsLawIsExported) {
  QTemporaryDir dir;
  const QString scene = dir.filePath(QStringLiteral("vessel.json"));
  QFile file(scene);
  ASSERT_TRUE(file.open(QIODevice::WriteOnly));
  file.write(R"({"objects": [{"type": "vessel", "rings": 3, "nodes_per_ring": 8,
      "material": {"youngs_modulus": 3.0e5, "fung_exponent": 6, "density": 1.06e-3}}]})");
  file.close();
  const QJsonObject net = exportScene({QStringLiteral("--scene"), scene}, dir.filePath(QStringLiteral("a.json")));
  const QJsonArray links = net.value(QStringLiteral("links")).toArray();
  ASSERT_FALSE(links.isEmpty());
  const QJsonObject link = links.at(0).toObject();
  EXPECT_EQ(link.value(QStringLiteral("law")).toString(), QStringLiteral("exponential"));
  EXPECT_GT(link.value(QStringLiteral("gain")).toDouble(), 0.0);
}

TEST(ExportCommand, Errors) {
  const CliRun bad = runCli({QStringLiteral("export"), QStringLiteral("--scene"),
                             QStringLiteral(MICROSIM_TEST_DATA_DIR "/scenes/malformed.json")});
  EXPECT_EQ(bad.exitCode, 1);
  EXPECT_TRUE(bad.err.contains(QStringLiteral("objects[0].links[1][1]"))) << bad.err.toStdString();
  EXPECT_EQ(runCli({QStringLiteral("export")}).exitCode, 2);
  EXPECT_EQ(
      runCli({QStringLiteral("export"), QStringLiteral("--lattice"), QStringLiteral("1")}).exitCode,
      2);
}

}  // namespace
