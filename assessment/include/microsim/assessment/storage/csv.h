#pragma once
// CSV as RFC 4180 writes it: fields separated by ',', records ended by CRLF; a field that
// holds ',', '"', CR or LF is enclosed in double quotes, with each '"' doubled.

#include <QString>
#include <QStringList>

namespace microsim::assessment {

QString csvField(const QString& field);

/// The fields joined by ',' and ended by "\r\n".
QString csvRecord(const QStringList& fields);

}  // namespace microsim::assessment
