#pragma once
// The app's tunables, declared once (STYLE.md §11): one table of {key, type, range or
// choices, default, label}. The settings dialog is built from it, QSettings stores the values
// under the keys, and value() reads them back with the default and range applied, so a
// stale or hand-edited settings file never yields a value outside the table.

#include <QCoreApplication>
#include <QString>
#include <QStringList>
#include <QVariant>

#include <vector>

namespace microsim::gui::settings {

struct Choice {
  QString value;  ///< stored
  QString label;  ///< shown, translated
  /// Offered only where this returns true (a mode this display can show); null: always.
  /// A stored value that is not offered reads back as the default.
  bool (*offered)() = nullptr;

  bool isOffered() const { return offered == nullptr || offered(); }
};

struct Tunable {
  enum class Type { Choice, Integer };
  QString key;  ///< QSettings key
  Type type = Type::Choice;
  std::vector<Choice> choices;  ///< Choice only, every one the app knows (see Choice::offered)
  int minimum = 0;              ///< Integer only
  int maximum = 0;              ///< Integer only
  QVariant defaultValue;
  QString label;                ///< translated
  QString help;                 ///< translated tool tip
  bool needsRestart = false;    ///< applied at the next start (the language)
};

/// Keys of the table, for the code that applies them.
inline QString solverKey() { return QStringLiteral("simulation/solver"); }
inline QString iterationsKey() { return QStringLiteral("simulation/iterations"); }
inline QString stereoKey() { return QStringLiteral("view/stereo"); }
inline QString keyMapKey() { return QStringLiteral("input/keyMap"); }
inline QString unitsKey() { return QStringLiteral("view/units"); }

class Tunables {
  Q_DECLARE_TR_FUNCTIONS(microsim::gui::settings::Tunables)

 public:
  /// The table, with labels in the current language.
  static std::vector<Tunable> all();
  /// The stored value of `key`, or its default when unset or out of range/choices.
  static QVariant value(const QString& key);
  /// Stores `value` (clamped/checked like value()).
  static void setValue(const QString& key, const QVariant& value);
};

}  // namespace microsim::gui::settings
