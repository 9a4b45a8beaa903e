#include "gui/number_format.h"

#include "gui/metric_vocabulary.h"

#include <QLocale>

#include <cmath>

namespace microsim::gui {

namespace {

QString notFinite() { return QStringLiteral("–"); }

// rounded to `decimals` places, then written with the fewest digits that read back as that
// rounded value: at most `decimals` places and no trailing zeros ("0.3", "60")
QString shortestRounded(double value, int decimals) {
  const double scale = std::pow(10.0, decimals);
  double rounded = std::round(value * scale) / scale;
  if (rounded == 0.0) rounded = 0.0;  // no "-0"
  return QLocale().toString(rounded, 'f', QLocale::FloatingPointShortest);
}

}  // namespace

QString NumberFormat::number(double value, int decimals) {
  if (!std::isfinite(value)) return notFinite();
  return QLocale().toString(value, 'f', decimals);
}

int NumberFormat::decimalsFor(std::string_view unit) {
  if (unit == "count" || unit == "flag") return 0;
  if (unit == "s" || unit == "deg") return 1;
  return 2;  // mm (10 µm steps), ratios
}

QString NumberFormat::value(double value, std::string_view unit, const QString& lengthUnits) {
  if (!std::isfinite(value)) return notFinite();
  if (unit == "mm" && lengthUnits == QLatin1String("um"))
    return shortestRounded(value * 1000.0, 0) + QStringLiteral(" µm");
  QString number = shortestRounded(value, decimalsFor(unit));
  const QString symbol = MetricVocabulary::unitSymbol(unit);
  if (symbol.isEmpty()) return number;
  if (symbol == QStringLiteral("°")) return number + symbol;
  return number + QLatin1Char(' ') + symbol;
}

QString NumberFormat::percent(double fraction) {
  if (!std::isfinite(fraction)) return notFinite();
  return QLocale().toString(std::round(fraction * 100.0), 'f', 0) + QStringLiteral(" %");
}

}  // namespace microsim::gui
