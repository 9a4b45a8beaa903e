// `microsim-cli bench scene --quick --json` as a user runs it: the default scene's rows carry
// every metric of issue 17 under their exact names, with finite and sensible values (no
// timing asserts beyond "the step took some time").
#include "support/cli_runner.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMap>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cmath>

namespace {

using microsim::testing::CliRun;
using microsim::testing::runCli;

TEST(BenchScene, QuickRunHasEveryMetricOfTheDefaultScene) {
  QTemporaryDir dir;
  const QString out = dir.filePath(QStringLiteral("scene.json"));
  const CliRun r = runCli({QStringLiteral("bench"), QStringLiteral("scene"), QStringLiteral("--quick"),
                           QStringLiteral("--json"), out});
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();

  QFile f(out);
  ASSERT_TRUE(f.open(QIODevice::ReadOnly));
  const QJsonDocument doc = QJsonDocument::fromJson(f.readAll());
  ASSERT_TRUE(doc.isArray());
  QMap<QString, double> anastomosis;
  for (const QJsonValue& v : doc.array()) {
    const QJsonObject row = v.toObject();
    EXPECT_EQ(row.value(QStringLiteral("bench")).toString(), QStringLiteral("scene"));
    // --quick leaves the fine scene out
    EXPECT_EQ(row.value(QStringLiteral("case")).toString(), QStringLiteral("anastomosis"));
    ASSERT_TRUE(row.value(QStringLiteral("value")).isDouble()) << row.value(QStringLiteral("metric")).toString().toStdString();
    anastomosis.insert(row.value(QStringLiteral("metric")).toString(), row.value(QStringLiteral("value")).toDouble());
  }

  for (const char* metric : {"step p99", "step median", "tissue error p99", "tissue error max", "max link stretch",
                             "interpenetrating pairs", "end gap at stitch"}) {
    ASSERT_TRUE(anastomosis.contains(QLatin1String(metric))) << metric;
    EXPECT_TRUE(std::isfinite(anastomosis.value(QLatin1String(metric)))) << metric;
    EXPECT_GE(anastomosis.value(QLatin1String(metric)), 0.0) << metric;
  }
  EXPECT_GT(anastomosis.value(QStringLiteral("step p99")), 0.0);
  EXPECT_GE(anastomosis.value(QStringLiteral("step p99")), anastomosis.value(QStringLiteral("step median")));
  EXPECT_GE(anastomosis.value(QStringLiteral("tissue error max")), anastomosis.value(QStringLiteral("tissue error p99")));
  EXPECT_GT(anastomosis.value(QStringLiteral("end gap at stitch")), 0.0);
  EXPECT_EQ(anastomosis.value(QStringLiteral("interpenetrating pairs")),
            std::floor(anastomosis.value(QStringLiteral("interpenetrating pairs"))));
  // the error was sampled at least 100 times, and the stitch pierced the walls
  EXPECT_GE(anastomosis.value(QStringLiteral("tissue error samples")), 100.0);
  EXPECT_GT(anastomosis.value(QStringLiteral("pierce events")), 0.0);
  // the per-stage times stay beside the step's
  EXPECT_TRUE(anastomosis.contains(QStringLiteral("tissue p99")));
  EXPECT_TRUE(anastomosis.contains(QStringLiteral("collision median")));
  EXPECT_GT(anastomosis.value(QStringLiteral("step p99 one replay")), 0.0);
  // the default scene is drawn as a smooth surface with at least as many points as the fine
  // pair has nodes (10,080), and it folds less between neighbouring triangles than the fine
  // pair's 70-sided rings do at rest (360°/70) at all but 1 % of its edges
  EXPECT_GE(anastomosis.value(QStringLiteral("drawn surface points")), 10080.0);
  EXPECT_LT(anastomosis.value(QStringLiteral("drawn surface fold p99")), 360.0 / 70.0);
  EXPECT_GE(anastomosis.value(QStringLiteral("drawn surface fold max")),
            anastomosis.value(QStringLiteral("drawn surface fold p99")));
  EXPECT_GE(anastomosis.value(QStringLiteral("step and drawn surface p99")),
            anastomosis.value(QStringLiteral("drawn surface median")));
}

}  // namespace
