// `microsim-cli solve` as a user runs it: real binary, scene files in a temporary dir.
#include "support/cli_runner.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace {

using microsim::testing::CliRun;
using microsim::testing::runCli;

QString writeFile(const QTemporaryDir& dir, const QString& name, const QByteArray& text) {
  QString path = dir.filePath(name);
  QFile f(path);
  EXPECT_TRUE(f.open(QIODevice::WriteOnly));
  f.write(text);
  return path;
}

QJsonObject readSolveJson(const QString& path) {
  QFile f(path);
  EXPECT_TRUE(f.open(QIODevice::ReadOnly)) << path.toStdString();
  return QJsonDocument::fromJson(f.readAll()).object();
}

QJsonArray position(const QJsonObject& doc, int node) {
  return doc.value(QStringLiteral("positions")).toArray().at(node).toArray();
}

// one free node hanging from a fixed one: k (l − r) = m g, so l = 1 + 1·10/50 = 1.2
TEST(SolveCommand, HangingSpringReachesTheClosedFormStretch) {
  QTemporaryDir dir;
  const QString scene = writeFile(dir, QStringLiteral("hang.json"), R"({
    "gravity": [0, 0, -10],
    "objects": [{"type": "spring-mesh", "nodes": [[0, 0, 0], [0, 0, -1]],
                 "links": [[0, 1, 50.0]], "fixed": [0]}]})");
  for (const char* solver : {"newton", "reference", "qss"}) {
    const QString out = dir.filePath(QStringLiteral("out_%1.json").arg(QLatin1String(solver)));
    const CliRun r = runCli(
        {QStringLiteral("solve"), QStringLiteral("--scene"), scene, QStringLiteral("--solver"),
         QLatin1String(solver), QStringLiteral("--iterations"), QStringLiteral("5000"),
         QStringLiteral("--tolerance"), QStringLiteral("1e-12"), QStringLiteral("--json"), out});
    ASSERT_EQ(r.exitCode, 0) << solver << " " << r.err.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("status"))) << r.out.toStdString();
    const QJsonObject doc = readSolveJson(out);
    EXPECT_EQ(doc.value(QStringLiteral("solver")).toString(), QLatin1String(solver));
    EXPECT_EQ(doc.value(QStringLiteral("status")).toString(), QStringLiteral("converged"))
        << solver;
    EXPECT_TRUE(doc.contains(QStringLiteral("iterations")));
    EXPECT_TRUE(doc.contains(QStringLiteral("seconds")));
    EXPECT_LE(doc.value(QStringLiteral("residual")).toDouble(), 1e-12);
    ASSERT_EQ(doc.value(QStringLiteral("positions")).toArray().size(), 2);
    EXPECT_EQ(position(doc, 0).at(2).toDouble(), 0.0);
    EXPECT_NEAR(position(doc, 1).at(0).toDouble(), 0.0, 1e-9) << solver;
    EXPECT_NEAR(position(doc, 1).at(2).toDouble(), -1.2, 1e-9) << solver;
  }
}

// fixed — free — controlled in a line: k1 (x − 1) = k2 (3 − x − 1) gives x = 1.75
TEST(SolveCommand, ChainBetweenFixedAndControlledNodes) {
  QTemporaryDir dir;
  const QString scene = writeFile(dir, QStringLiteral("chain.json"), R"({
    "objects": [{"type": "spring-mesh", "nodes": [[0, 0, 0], [1, 0, 0], [2, 0, 0]],
                 "links": [[0, 1, 10], [1, 2, 30]], "fixed": [0],
                 "controls": [{"node": 2, "displacement": [1, 0, 0]}]}],
    "solver": {"name": "newton", "iterations": 100}})");
  const QString out = dir.filePath(QStringLiteral("out.json"));
  const CliRun r = runCli({QStringLiteral("solve"), QStringLiteral("--scene"), scene,
                           QStringLiteral("--tolerance"), QStringLiteral("1e-12"),
                           QStringLiteral("--json"), out});
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();
  const QJsonObject doc = readSolveJson(out);
  EXPECT_EQ(doc.value(QStringLiteral("solver")).toString(), QStringLiteral("newton"));
  EXPECT_NEAR(position(doc, 1).at(0).toDouble(), 1.75, 1e-9);
  EXPECT_NEAR(position(doc, 2).at(0).toDouble(), 3.0, 1e-12);
}

TEST(SolveCommand, LatticeProtocol) {
  QTemporaryDir dir;
  const QString out = dir.filePath(QStringLiteral("lattice.json"));
  const CliRun r =
      runCli({QStringLiteral("solve"), QStringLiteral("--lattice"), QStringLiteral("4"),
              QStringLiteral("--solver"), QStringLiteral("qss"), QStringLiteral("--iterations"),
              QStringLiteral("10"), QStringLiteral("--cutout"), QStringLiteral("0.001"),
              QStringLiteral("--json"), out});
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();
  const QJsonObject doc = readSolveJson(out);
  EXPECT_EQ(doc.value(QStringLiteral("positions")).toArray().size(), 64);
  EXPECT_EQ(doc.value(QStringLiteral("iterations")).toInt(), 10);
  EXPECT_EQ(doc.value(QStringLiteral("status")).toString(), QStringLiteral("iteration-limit"));
  // the top middle node (2, 2, 3) sits at its target, the bottom stays put
  const int top = 2 + 4 * (2 + 4 * 3);
  EXPECT_DOUBLE_EQ(position(doc, top).at(2).toDouble(), 4.0);
  EXPECT_DOUBLE_EQ(position(doc, 5).at(2).toDouble(), 0.0);
}

TEST(SolveCommand, MalformedSceneExitsOneAndNamesTheField) {
  QTemporaryDir dir;
  const QString scene = writeFile(dir, QStringLiteral("bad.json"),
                                  "{\"objects\": [{\"type\": \"spring-mesh\",\n"
                                  "  \"nodes\": [[0, 0, 0], [1, 0, 0]],\n"
                                  "  \"links\": [[0, 1, 50.0], [0, 0, 50.0]]}]}");
  const CliRun r =
      runCli({QStringLiteral("solve"), QStringLiteral("--scene"), scene, QStringLiteral("--solver"),
              QStringLiteral("qss"), QStringLiteral("--iterations"), QStringLiteral("5")});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_TRUE(r.err.contains(QStringLiteral("objects[0].links[1]"))) << r.err.toStdString();
  EXPECT_TRUE(r.err.contains(QStringLiteral("bad.json:3:"))) << r.err.toStdString();

  const CliRun syntax = runCli({QStringLiteral("solve"), QStringLiteral("--scene"),
                                writeFile(dir, QStringLiteral("syntax.json"), "{\"objects\": [\n}"),
                                QStringLiteral("--iterations"), QStringLiteral("5")});
  EXPECT_EQ(syntax.exitCode, 1);
  EXPECT_TRUE(syntax.err.contains(QStringLiteral("syntax.json:2:1"))) << syntax.err.toStdString();

  const CliRun missing = runCli({QStringLiteral("solve"), QStringLiteral("--scene"),
                                 dir.filePath(QStringLiteral("none.json")),
                                 QStringLiteral("--iterations"), QStringLiteral("5")});
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_TRUE(missing.err.contains(QStringLiteral("none.json"))) << missing.err.toStdString();
}

TEST(SolveCommand, BadArgumentsExitTwo) {
  const QString L = QStringLiteral("--lattice");
  const QString three = QStringLiteral("3");
  const QString it = QStringLiteral("--iterations");
  const QString five = QStringLiteral("5");
  const CliRun unknown = runCli({QStringLiteral("solve"), L, three, QStringLiteral("--solver"),
                                 QStringLiteral("magic"), it, five});
  EXPECT_EQ(unknown.exitCode, 2);
  EXPECT_TRUE(unknown.err.contains(QStringLiteral("unknown solver 'magic'")))
      << unknown.err.toStdString();
  EXPECT_TRUE(unknown.err.contains(QStringLiteral("qss")));

  EXPECT_EQ(runCli({QStringLiteral("solve"), L, three}).exitCode, 2);  // no limit
  EXPECT_EQ(runCli({QStringLiteral("solve"), it, five}).exitCode, 2);  // no network
  EXPECT_EQ(runCli({QStringLiteral("solve"), L, three, QStringLiteral("--scene"),
                    QStringLiteral("x.json"), it, five})
                .exitCode,
            2);
  EXPECT_EQ(runCli({QStringLiteral("solve"), L, QStringLiteral("one"), it, five}).exitCode, 2);
  EXPECT_EQ(runCli({QStringLiteral("solve"), L, three, it, QStringLiteral("0")}).exitCode, 2);
  EXPECT_EQ(runCli({QStringLiteral("solve"), L, three, it, five, QStringLiteral("--alpha"),
                    QStringLiteral("-1")})
                .exitCode,
            2);
  EXPECT_EQ(runCli({QStringLiteral("solve"), L, three, it, five, QStringLiteral("--momentum"),
                    QStringLiteral("1")})
                .exitCode,
            2);
  EXPECT_EQ(runCli({QStringLiteral("solve"), L, three, it, five, QStringLiteral("--frobnicate")})
                .exitCode,
            2);
  const CliRun help = runCli({QStringLiteral("solve"), QStringLiteral("--help")});
  EXPECT_EQ(help.exitCode, 0);
  EXPECT_TRUE(help.out.contains(QStringLiteral("--budget-ms")));
}

}  // namespace
