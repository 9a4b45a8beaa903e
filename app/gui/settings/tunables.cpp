#include "gui/settings/tunables.h"

#include "gui/render/stereo_support.h"
#include "i18n/translations.h"

#include <QSettings>

#include <algorithm>

namespace microsim::gui::settings {

std::vector<Tunable> Tunables::all() {
  using Type = Tunable::Type;
  std::vector<Tunable> table;
  table.push_back({solverKey(), Type::Choice,
                   {{QStringLiteral("scene"), tr("As the lesson's scene says")},
                    {QStringLiteral("qss"), tr("Quasi-static (the paper's)")},
                    {QStringLiteral("newton"), tr("Newton with multigrid")},
                    {QStringLiteral("implicit"), tr("Implicit Euler")}},
                   0, 0, QStringLiteral("scene"), tr("Tissue solver"),
                   tr("The tissue solver of live attempts; graded replays use the same one."), false});
  table.push_back({iterationsKey(), Type::Integer, {}, 0, 500, 0, tr("Iteration budget"),
                   tr("Solver iterations per step; 0 keeps the scene's."), false});
  table.push_back({stereoKey(), Type::Choice,
                   {{QStringLiteral("mono"), tr("Mono")},
                    {QStringLiteral("quad"), tr("Quad-buffer stereo"), &quadBufferStereoAvailable},
                    {QStringLiteral("anaglyph"), tr("Anaglyph (red/cyan)")},
                    {QStringLiteral("side"), tr("Side by side")}},
                   0, 0, QStringLiteral("mono"), tr("Stereo"),
                   tr("How the microscope's two eyes are shown. Quad-buffer stereo is offered only where the "
                      "display has left and right buffers."),
                   false});
  table.push_back({keyMapKey(), Type::Choice,
                   {{QStringLiteral("qwerty"), tr("QWERTY / QWERTZ (W A S D, Q E)")},
                    {QStringLiteral("azerty"), tr("AZERTY (Z Q S D, A E)")}},
                   0, 0, QStringLiteral("qwerty"), tr("Key map"),
                   tr("Which letter keys move the tools; the arrows and Space stay the same."), false});
  table.push_back({unitsKey(), Type::Choice,
                   {{QStringLiteral("mm"), tr("Millimetres")}, {QStringLiteral("um"), tr("Micrometres")}},
                   0, 0, QStringLiteral("mm"), tr("Length units"),
                   tr("Units of lengths on the results page."), false});
  // each language named in itself and never translated, as language lists do, so that whoever
  // cannot read the interface's present language still finds their own (QLocale's native names
  // say "American English")
  table.push_back({i18n::languageSettingKey(),
                   Type::Choice,
                   {{QString(), tr("System default")},
                    {QStringLiteral("en"), QStringLiteral("English")},
                    {QStringLiteral("de"), QStringLiteral("Deutsch")},
                    {QStringLiteral("es"), QString::fromUtf8("Español")}},
                   0,
                   0,
                   QString(),
                   tr("Language"),
                   tr("The interface language."),
                   true});
  return table;
}

namespace {

const Tunable* find(const std::vector<Tunable>& table, const QString& key) {
  const auto it = std::find_if(table.begin(), table.end(), [&](const Tunable& t) { return t.key == key; });
  return it == table.end() ? nullptr : &*it;
}

QVariant checked(const Tunable& t, const QVariant& v) {
  if (!v.isValid()) return t.defaultValue;
  if (t.type == Tunable::Type::Integer) {
    bool ok = false;
    const int i = v.toInt(&ok);
    return ok ? QVariant(std::clamp(i, t.minimum, t.maximum)) : t.defaultValue;
  }
  const QString s = v.toString();
  const bool known =
      std::any_of(t.choices.begin(), t.choices.end(), [&](const Choice& c) { return c.value == s && c.isOffered(); });
  return known ? QVariant(s) : t.defaultValue;
}

}  // namespace

QVariant Tunables::value(const QString& key) {
  const std::vector<Tunable> table = all();
  const Tunable* t = find(table, key);
  if (!t) return {};
  return checked(*t, QSettings().value(key));
}

void Tunables::setValue(const QString& key, const QVariant& value) {
  const std::vector<Tunable> table = all();
  if (const Tunable* t = find(table, key)) QSettings().setValue(key, checked(*t, value));
}

}  // namespace microsim::gui::settings
