#include "microsim/assessment/storage/csv.h"

namespace microsim::assessment {

QString csvField(const QString& field) {
  static const QString special = QStringLiteral(",\"\r\n");
  bool quote = false;
  for (QChar c : field) quote = quote || special.contains(c);
  if (!quote) return field;
  QString out = field;
  out.replace(QLatin1String("\""), QLatin1String("\"\""));
  return QLatin1Char('"') + out + QLatin1Char('"');
}

QString csvRecord(const QStringList& fields) {
  QStringList quoted;
  quoted.reserve(fields.size());
  for (const QString& f : fields) quoted << csvField(f);
  return quoted.join(QLatin1Char(',')) + QStringLiteral("\r\n");
}

}  // namespace microsim::assessment
