#pragma once
// Checks a man page source (packaging/*.1.in) against a program's own --help text, so the
// installed manual cannot fall behind the options the program takes.
#include <QFile>
#include <QRegularExpression>
#include <QString>
#include <QStringList>

namespace microsim::testing {

/// The text of the man page source `name` (e.g. "microsim-cli.1.in") in packaging/.
inline QString manPageSource(const QString& name) {
  QFile file(QStringLiteral(MICROSIM_SOURCE_DIR "/packaging/") + name);
  if (!file.open(QIODevice::ReadOnly)) return {};
  return QString::fromUtf8(file.readAll());
}

/// `word` as roff source spells it: each hyphen escaped, "--scene" → "\-\-scene".
inline QString roffWord(QString word) { return word.replace(QLatin1Char('-'), QStringLiteral("\\-")); }

/// Every long option ("--json") named in `help` that `manPage` does not mention.
inline QStringList optionsMissingFromManPage(const QString& help, const QString& manPage) {
  QStringList missing;
  static const QRegularExpression option(QStringLiteral("--[a-z][a-z0-9-]*"));
  for (auto it = option.globalMatch(help); it.hasNext();) {
    const QString name = it.next().captured();
    if (!manPage.contains(roffWord(name)) && !missing.contains(name)) missing << name;
  }
  return missing;
}

}  // namespace microsim::testing
