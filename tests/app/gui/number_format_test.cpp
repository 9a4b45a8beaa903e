// Numbers in the interface's locale: one helper for every number a page shows with its unit.
#include "gui/number_format.h"

#include <QLocale>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace microsim::gui {
namespace {

// the default locale set to `locale` for one test, as the app's start-up sets it
class DefaultLocaleForNumbers {
 public:
  explicit DefaultLocaleForNumbers(const QLocale& locale) { QLocale::setDefault(locale); }
  ~DefaultLocaleForNumbers() { QLocale::setDefault(previous_); }
  DefaultLocaleForNumbers(const DefaultLocaleForNumbers&) = delete;
  DefaultLocaleForNumbers& operator=(const DefaultLocaleForNumbers&) = delete;

 private:
  QLocale previous_;
};

TEST(NumberFormat, WritesValuesWithTheirUnitsInTheLocalesFormat) {
  {
    const DefaultLocaleForNumbers german(QLocale(QLocale::German, QLocale::Germany));
    EXPECT_EQ(NumberFormat::value(26.94, "s"), QStringLiteral("26,9 s"));
    EXPECT_EQ(NumberFormat::value(0.3, "mm"), QStringLiteral("0,3 mm"));
    EXPECT_EQ(NumberFormat::value(0.384, "mm"), QStringLiteral("0,38 mm"));
    EXPECT_EQ(NumberFormat::value(58.04, "deg"), QStringLiteral("58°"));
    EXPECT_EQ(NumberFormat::value(1.725, "1"), QStringLiteral("1,73"));
    EXPECT_EQ(NumberFormat::value(2.0, "count"), QStringLiteral("2"));
    EXPECT_EQ(NumberFormat::value(0.35, "mm", QStringLiteral("um")), QStringLiteral("350 µm"));
    EXPECT_EQ(NumberFormat::number(87.5, 1), QStringLiteral("87,5"));
    EXPECT_EQ(NumberFormat::number(90.0, 1), QStringLiteral("90,0"));
    EXPECT_EQ(NumberFormat::number(1234.5, 1), QStringLiteral("1.234,5"));
    EXPECT_EQ(NumberFormat::percent(0.624), QStringLiteral("62 %"));
  }
  {
    const DefaultLocaleForNumbers spanish(QLocale(QLocale::Spanish, QLocale::Spain));
    EXPECT_EQ(NumberFormat::value(26.94, "s"), QStringLiteral("26,9 s"));
  }
  const DefaultLocaleForNumbers english(QLocale(QLocale::English, QLocale::UnitedStates));
  EXPECT_EQ(NumberFormat::value(26.94, "s"), QStringLiteral("26.9 s"));
  EXPECT_EQ(NumberFormat::value(0.3, "mm"), QStringLiteral("0.3 mm"));
  EXPECT_EQ(NumberFormat::number(87.5, 1), QStringLiteral("87.5"));
}

TEST(NumberFormat, ShowsADashForWhatWasNotMeasuredAndNoNegativeZero) {
  EXPECT_EQ(NumberFormat::value(std::nan(""), "s"), QStringLiteral("–"));
  EXPECT_EQ(NumberFormat::value(std::numeric_limits<double>::infinity(), "mm"), QStringLiteral("–"));
  EXPECT_EQ(NumberFormat::number(std::nan(""), 1), QStringLiteral("–"));
  EXPECT_EQ(NumberFormat::percent(std::nan("")), QStringLiteral("–"));
  const DefaultLocaleForNumbers english(QLocale(QLocale::English, QLocale::UnitedStates));
  EXPECT_EQ(NumberFormat::value(-0.001, "mm"), QStringLiteral("0 mm"));
}

TEST(NumberFormat, UnitsDecideThePlaces) {
  EXPECT_EQ(NumberFormat::decimalsFor("s"), 1);
  EXPECT_EQ(NumberFormat::decimalsFor("deg"), 1);
  EXPECT_EQ(NumberFormat::decimalsFor("mm"), 2);
  EXPECT_EQ(NumberFormat::decimalsFor("1"), 2);
  EXPECT_EQ(NumberFormat::decimalsFor("count"), 0);
}

}  // namespace
}  // namespace microsim::gui
