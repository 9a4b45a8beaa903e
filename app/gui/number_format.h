#pragma once
// Numbers as the user reads them: in the format of the interface's locale (QLocale(), which
// i18n::installTranslations sets to the interface language: "26,9 s" in German, "26.9 s" in
// English) with the unit's symbol from the metric vocabulary, and one rule for how many places
// each unit shows, so that the results page, the review, the charts and the PDF agree.
// Machine-readable output (CSV, JSON, the CLI's tables) does not come here: it keeps '.'.

#include <QString>

#include <string_view>

namespace microsim::gui {

class NumberFormat {
 public:
  /// `value` with exactly `decimals` places in the locale's format ("87,5", "90,0"), for
  /// tables and scores whose digits should line up; "–" when not finite.
  static QString number(double value, int decimals);

  /// How many places a value in `unit` ("s", "mm", "deg", "count", "1", ...) is shown with:
  /// s and deg 1, mm and ratios 2, counts 0.
  static int decimalsFor(std::string_view unit);

  /// A measured value with its unit's symbol: "26,9 s", "0,3 mm", "58°", "3" for a count;
  /// rounded to decimalsFor(unit) places with trailing zeros dropped; "–" when not finite.
  /// With `lengthUnits` "um" a length in mm is shown in whole micrometres ("350 µm").
  static QString value(double value, std::string_view unit, const QString& lengthUnits = QString());

  /// A fraction as a whole percentage in the locale's format: "62 %" for 0.62.
  static QString percent(double fraction);
};

}  // namespace microsim::gui
