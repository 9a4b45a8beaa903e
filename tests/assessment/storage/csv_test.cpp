#include "microsim/assessment/storage/csv.h"

#include <gtest/gtest.h>

namespace microsim::assessment {
namespace {

TEST(Csv, QuotesOnlyFieldsThatNeedIt) {
  EXPECT_EQ(csvField(QStringLiteral("Ana")).toStdString(), "Ana");
  EXPECT_EQ(csvField(QString()).toStdString(), "");
  EXPECT_EQ(csvField(QStringLiteral("Doe, John")).toStdString(), "\"Doe, John\"");
  EXPECT_EQ(csvField(QStringLiteral("say \"hi\"")).toStdString(), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(csvField(QStringLiteral("two\nlines")).toStdString(), "\"two\nlines\"");
  EXPECT_EQ(csvField(QStringLiteral("cr\rhere")).toStdString(), "\"cr\rhere\"");
  EXPECT_EQ(csvField(QStringLiteral("x'); DROP TABLE attempts;--")).toStdString(),
            "x'); DROP TABLE attempts;--");
}

TEST(Csv, RecordsEndWithCrLf) {
  EXPECT_EQ(csvRecord({QStringLiteral("a"), QStringLiteral("b,c"), QString()}).toStdString(),
            "a,\"b,c\",\r\n");
}

}  // namespace
}  // namespace microsim::assessment
