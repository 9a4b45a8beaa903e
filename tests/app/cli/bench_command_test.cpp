// `microsim-cli bench table1 --quick` as a user runs it: the JSON rows' shape, and the
// paper's figure beside ours on every row the paper has (no timing asserts).
#include "support/cli_runner.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSet>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace {

using microsim::testing::CliRun;
using microsim::testing::runCli;

TEST(BenchCommand, Table1QuickWritesRowsWithThePapersFigures) {
  QTemporaryDir dir;
  const QString out = dir.filePath(QStringLiteral("table1.json"));
  const CliRun r = runCli({QStringLiteral("bench"), QStringLiteral("table1"), QStringLiteral("--quick"),
                           QStringLiteral("--json"), out});
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();

  QFile f(out);
  ASSERT_TRUE(f.open(QIODevice::ReadOnly));
  const QJsonDocument doc = QJsonDocument::fromJson(f.readAll());
  ASSERT_TRUE(doc.isArray());
  const QJsonArray rows = doc.array();
  // the quick run: 6³, 8³, 10³, each without and with the cutout
  ASSERT_EQ(rows.size(), 6);
  QSet<QString> cases;
  for (const QJsonValue& v : rows) {
    const QJsonObject row = v.toObject();
    EXPECT_EQ(row.value(QStringLiteral("bench")).toString(), QStringLiteral("table1"));
    EXPECT_EQ(row.value(QStringLiteral("metric")).toString(), QStringLiteral("iterations per 1/30 s"));
    EXPECT_EQ(row.value(QStringLiteral("unit")).toString(), QStringLiteral("iterations"));
    ASSERT_TRUE(row.value(QStringLiteral("value")).isDouble());
    EXPECT_GT(row.value(QStringLiteral("value")).toDouble(), 0.0);
    // every quick size is in the paper's Table 1: its figure and our ratio to it
    ASSERT_TRUE(row.value(QStringLiteral("paper")).isDouble()) << row.value(QStringLiteral("case")).toString().toStdString();
    EXPECT_GT(row.value(QStringLiteral("paper")).toDouble(), 0.0);
    ASSERT_TRUE(row.value(QStringLiteral("ratio")).isDouble());
    EXPECT_NEAR(row.value(QStringLiteral("ratio")).toDouble(),
                row.value(QStringLiteral("value")).toDouble() / row.value(QStringLiteral("paper")).toDouble(), 1e-9);
    cases.insert(row.value(QStringLiteral("case")).toString());
  }
  for (const char* c : {"6^3 without cutout", "6^3 with cutout", "8^3 without cutout", "8^3 with cutout",
                        "10^3 without cutout", "10^3 with cutout"})
    EXPECT_TRUE(cases.contains(QLatin1String(c))) << c;
  // the paper's figures for those rows
  for (const QJsonValue& v : rows) {
    const QJsonObject row = v.toObject();
    const QString c = row.value(QStringLiteral("case")).toString();
    if (c == QStringLiteral("6^3 without cutout"))
      EXPECT_EQ(row.value(QStringLiteral("paper")).toDouble(), 24.0);
    if (c == QStringLiteral("6^3 with cutout"))
      EXPECT_EQ(row.value(QStringLiteral("paper")).toDouble(), 248.0);
  }
}

}  // namespace
