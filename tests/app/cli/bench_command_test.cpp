// `microsim-cli bench table1 --quick` as a user runs it: the JSON rows' shape, the paper's
// figure beside ours on every row the paper has, and the progress lines on stderr that
// never reach stdout or the JSON (no timing asserts).
#include "support/cli_runner.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>
#include <QList>
#include <QRegularExpression>
#include <QSet>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace {

using microsim::testing::CliRun;
using microsim::testing::runCli;

/// `bench table1 --quick --json OUT`
CliRun runTable1Quick(const QString& out) {
  return runCli({QStringLiteral("bench"), QStringLiteral("table1"), QStringLiteral("--quick"),
                 QStringLiteral("--json"), out});
}

TEST(BenchCommand, Table1QuickWritesRowsWithThePapersFigures) {
  QTemporaryDir dir;
  const QString out = dir.filePath(QStringLiteral("table1.json"));
  const CliRun r = runTable1Quick(out);
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
    if (c == QStringLiteral("6^3 without cutout")) {
      EXPECT_EQ(row.value(QStringLiteral("paper")).toDouble(), 24.0);
    }
    if (c == QStringLiteral("6^3 with cutout")) {
      EXPECT_EQ(row.value(QStringLiteral("paper")).toDouble(), 248.0);
    }
  }
}

TEST(BenchCommand, QuickRunShowsItsCasesOnStderrAndKeepsStdoutAndTheJsonClean) {
  QTemporaryDir dir;
  const QString out = dir.filePath(QStringLiteral("table1.json"));
  const CliRun r = runTable1Quick(out);
  ASSERT_EQ(r.exitCode, 0) << r.err.toStdString();

  // stderr: "table1: [k/3] BOX (S s)" as the cases start, at most one line a second: the
  // first case always, a later one unless a newer case or the end came first
  const QRegularExpression progress(QStringLiteral("^table1: \\[(\\d+)/(\\d+)\\] (.+) \\((\\d+) s\\)$"));
  const QStringList boxes = {QStringLiteral("6^3"), QStringLiteral("8^3"), QStringLiteral("10^3")};
  QList<int> shown;
  for (const QString& line : r.err.split(QLatin1Char('\n'), Qt::SkipEmptyParts)) {
    const QRegularExpressionMatch m = progress.match(line);
    if (!m.hasMatch()) continue;  // Qt's own warnings may share stderr
    const int k = m.captured(1).toInt();
    EXPECT_EQ(m.captured(2).toInt(), 3) << line.toStdString();
    ASSERT_TRUE(k >= 1 && k <= 3) << line.toStdString();
    EXPECT_EQ(m.captured(3), boxes[k - 1]) << line.toStdString();
    if (!shown.isEmpty()) {
      EXPECT_GT(k, shown.back()) << line.toStdString();
    }
    shown << k;
  }
  ASSERT_FALSE(shown.isEmpty()) << r.err.toStdString();
  EXPECT_EQ(shown.front(), 1);

  // stdout: the table, and no progress
  EXPECT_TRUE(r.out.contains(QStringLiteral("6^3 without cutout"))) << r.out.toStdString();
  EXPECT_FALSE(r.out.contains(QStringLiteral("table1: ["))) << r.out.toStdString();

  // the JSON file: the array of rows and nothing else
  QFile f(out);
  ASSERT_TRUE(f.open(QIODevice::ReadOnly));
  const QByteArray bytes = f.readAll();
  EXPECT_FALSE(bytes.contains("table1: ["));
  QJsonParseError error;
  const QJsonDocument doc = QJsonDocument::fromJson(bytes, &error);
  ASSERT_EQ(error.error, QJsonParseError::NoError) << error.errorString().toStdString();
  ASSERT_TRUE(doc.isArray());
  EXPECT_EQ(doc.array().size(), 6);
  for (const QJsonValue& v : doc.array()) {
    ASSERT_TRUE(v.isObject());
    for (const char* key : {"bench", "case", "metric", "value", "unit"})
      EXPECT_TRUE(v.toObject().contains(QLatin1String(key))) << key;
  }
}

}  // namespace
